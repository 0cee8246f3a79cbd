#include "core/DivisionOverflowTrap.h"

#include <atomic>
#include <csignal>
#include <cstdint>
#include <cstring>
#include <mutex>

#if defined(__x86_64__) && defined(__linux__)
#include <ucontext.h>
#define TOYHOST_TRAP_IDIV 1
#endif

namespace toyhost {

namespace {

std::mutex installMutex;
int holders = 0;
struct sigaction previous {};
std::atomic<long> emulatedCount{0};

#ifdef TOYHOST_TRAP_IDIV
// gregs index of x86-64 register number 0..15 (the ModRM / SIB encoding order).
constexpr int kRegister[16] = {REG_RAX, REG_RCX, REG_RDX, REG_RBX, REG_RSP, REG_RBP, REG_RSI, REG_RDI,
                               REG_R8,  REG_R9,  REG_R10, REG_R11, REG_R12, REG_R13, REG_R14, REG_R15};

// The `idiv r/m32` or `idiv r/m64` at `ip`: its length and its divisor's value, read from the
// register or memory operand as the CPU would. False for anything else.
bool decodeIdiv(const std::uint8_t* ip, const greg_t* regs, int& length, bool& wide, std::int64_t& divisor) {
    int at = 0;
    std::uint8_t rex = 0;
    if ((ip[at] & 0xF0) == 0x40) rex = ip[at++];
    if (ip[at++] != 0xF7) return false;
    const std::uint8_t modrm = ip[at++];
    const int mod = modrm >> 6, reg = (modrm >> 3) & 7, rm = modrm & 7;
    if (reg != 7) return false;  // F7 /7 is idiv
    wide = (rex & 0x08) != 0;
    auto value = [&](std::uint64_t raw) {
        return wide ? static_cast<std::int64_t>(raw) : static_cast<std::int64_t>(static_cast<std::int32_t>(raw));
    };
    if (mod == 3) {
        length = at;
        divisor = value(static_cast<std::uint64_t>(regs[kRegister[rm | ((rex & 1) << 3)]]));
        return true;
    }
    std::uint64_t address = 0;
    if (rm == 4) {  // SIB
        const std::uint8_t sib = ip[at++];
        const int scale = sib >> 6, index = ((sib >> 3) & 7) | ((rex & 2) << 2), base = (sib & 7) | ((rex & 1) << 3);
        if (index != 4) address += static_cast<std::uint64_t>(regs[kRegister[index]]) << scale;
        if ((base & 7) == 5 && mod == 0) {
            std::int32_t disp;
            std::memcpy(&disp, ip + at, 4);
            at += 4;
            address += static_cast<std::uint64_t>(static_cast<std::int64_t>(disp));
        } else {
            address += static_cast<std::uint64_t>(regs[kRegister[base]]);
        }
    } else if (rm == 5 && mod == 0) {  // RIP-relative: from the end of the instruction
        std::int32_t disp;
        std::memcpy(&disp, ip + at, 4);
        at += 4;
        address = reinterpret_cast<std::uint64_t>(ip) + static_cast<std::uint64_t>(at) +
                  static_cast<std::uint64_t>(static_cast<std::int64_t>(disp));
    } else {
        address = static_cast<std::uint64_t>(regs[kRegister[rm | ((rex & 1) << 3)]]);
    }
    if (mod == 1) {
        address += static_cast<std::uint64_t>(static_cast<std::int64_t>(static_cast<std::int8_t>(ip[at])));
        at += 1;
    } else if (mod == 2) {
        std::int32_t disp;
        std::memcpy(&disp, ip + at, 4);
        at += 4;
        address += static_cast<std::uint64_t>(static_cast<std::int64_t>(disp));
    }
    length = at;
    std::uint64_t raw = 0;
    std::memcpy(&raw, reinterpret_cast<const void*>(address), wide ? 8 : 4);
    divisor = value(raw);
    return true;
}

void onDivisionFault(int signal, siginfo_t* info, void* context) {
    auto* uc = static_cast<ucontext_t*>(context);
    greg_t* regs = uc->uc_mcontext.gregs;
    const auto* ip = reinterpret_cast<const std::uint8_t*>(regs[REG_RIP]);
    int length = 0;
    bool wide = false;
    std::int64_t divisor = 0;
    if (info->si_code == FPE_INTDIV && decodeIdiv(ip, regs, length, wide, divisor) && divisor == -1) {
        const bool minimum = wide ? regs[REG_RAX] == static_cast<greg_t>(INT64_MIN)
                                  : static_cast<std::uint32_t>(regs[REG_RAX]) == 0x80000000u;
        if (minimum) {
            // As the browsers fold it (ANGLE's constant folder, checked in headless Chromium with
            // ../shared/webref's int_divzero_const and cp_const_intmin_div probes): the quotient
            // saturates to the largest integer, the remainder is 0 (a 32-bit result zero-extends
            // into the 64-bit register, as the CPU writes it).
            regs[REG_RAX] = wide ? static_cast<greg_t>(INT64_MAX) : static_cast<greg_t>(0x7fffffffu);
            regs[REG_RDX] = 0;
            regs[REG_RIP] += length;
            emulatedCount.fetch_add(1, std::memory_order_relaxed);
            return;
        }
    }
    // Not ours: the previous handling takes it when the instruction runs again (by default the
    // process ends with SIGFPE, as it did without the trap).
    sigaction(signal, &previous, nullptr);
}
#endif

}  // namespace

DivisionOverflowTrap::DivisionOverflowTrap() {
#ifdef TOYHOST_TRAP_IDIV
    std::lock_guard lock(installMutex);
    if (holders++ > 0) return;
    struct sigaction action {};
    action.sa_sigaction = onDivisionFault;
    action.sa_flags = SA_SIGINFO | SA_NODEFER;
    sigemptyset(&action.sa_mask);
    sigaction(SIGFPE, &action, &previous);
#endif
}

DivisionOverflowTrap::~DivisionOverflowTrap() {
#ifdef TOYHOST_TRAP_IDIV
    std::lock_guard lock(installMutex);
    if (--holders > 0) return;
    sigaction(SIGFPE, &previous, nullptr);
#endif
}

long DivisionOverflowTrap::emulated() { return emulatedCount.load(std::memory_order_relaxed); }

}  // namespace toyhost
