// The public lists as data: toyhost::runDefaults (toyhost/Defaults.h) and toyhost::settingFields
// (toyhost/Settings.h), both made from their one list. No GL needed.
#include <toyhost/Defaults.h>
#include <toyhost/Settings.h>

namespace toyhost {

Defaults runDefaults() { return Defaults{}; }

std::span<const SettingField> settingFields() {
#define TOYHOST_SETTINGS_ROW(Type, member, key, initial, fallback) SettingField{#member, key, #fallback},
    static constexpr SettingField kFields[] = {TOYHOST_SESSION_SETTINGS(TOYHOST_SETTINGS_ROW)};
#undef TOYHOST_SETTINGS_ROW
    return kFields;
}

}  // namespace toyhost
