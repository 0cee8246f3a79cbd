// libFuzzer target: the farm's files (runtime/farm/): byte 0 picks what the rest is. Even: a
// farm.json through layoutFromPlan, and a read layout's frame names and counts; odd: a GNU parallel
// joblog through exitCodesFromJoblog. Then the rest cut at NUL bytes is a plan request (job folder,
// --time, frame name, run options) through planFarm: a value holding a line break, CR or NUL that
// is planned anyway, or a farm.json that does not read back, traps.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "farm/FarmPlan.h"
#include "farm/FarmStatus.h"

namespace {

bool endsALine(const std::string& value) { return value.find_first_of(std::string("\n\r\0", 3)) != std::string::npos; }

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0) return 0;
    const std::string text(reinterpret_cast<const char*>(data) + 1, size - 1);
    using namespace toyhost::farm;
    if (data[0] % 2 == 0) {
        toyhost::Result<FrameLayout> layout = layoutFromPlan(text, "/job");
        if (layout) {
            for (int frame : {0, layout->frames - 1, layout->frames / 2}) (void)layout->frameFile(frame);
            const toyhost::FrameSpan all{0, layout->frames};
            (void)layout->capturedCount(0, layout->frames - 1, all);
            (void)layout->frameNumberOf(layout->frameFile(layout->frames - 1).filename().string());
        } else {
            volatile std::size_t length = layout.error().text().size();
            (void)length;
        }
    } else {
        (void)exitCodesFromJoblog(text);
    }
    (void)frameNameProblem(text);
    (void)slurmTimeProblem(text);

    std::vector<std::string> values;
    for (std::size_t at = 0;;) {
        const std::size_t nul = text.find('\0', at);
        values.push_back(text.substr(at, nul == std::string::npos ? std::string::npos : nul - at));
        if (nul == std::string::npos || values.size() == 8) break;
        at = nul + 1;
    }
    PlanRequest r;
    r.scheduler = data[0] % 3 == 0 ? Scheduler::Slurm : data[0] % 3 == 1 ? Scheduler::Kubernetes : Scheduler::Parallel;
    r.target = "/srv/toy";
    r.jobDir = "/" + values[0];
    r.frames = 1 + data[0] % 7;
    r.shards = 1 + data[0] % 3 % r.frames;
    r.stateful = data[0] & 8;
    if (values.size() > 1) r.slurmTime = values[1];
    if (values.size() > 2 && !values[2].empty()) r.frameName = values[2];
    r.runOptions.assign(values.begin() + std::min<std::size_t>(values.size(), 3), values.end());
    toyhost::Result<std::vector<PlanFile>> files = planFarm(r);
    if (!files) return 0;
    if (endsALine(r.jobDir) || endsALine(r.slurmTime) || endsALine(r.frameName)) __builtin_trap();
    for (const std::string& option : r.runOptions)
        if (endsALine(option)) __builtin_trap();
    if (!layoutFromPlan(files->front().text, r.jobDir)) __builtin_trap();  // farm.json reads back
    return 0;
}
