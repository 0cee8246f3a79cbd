// DivisionOverflowTrap: INT_MIN / -1 by the CPU's idiv (as Mesa's constant folder does it) gives
// the two's-complement answer while a trap lives, for register and memory divisors, 32 and 64
// bits; without the trap, and for a division by zero even with it, the process still ends with
// SIGFPE (checked in forked children).
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <climits>
#include <cstdint>

#include "core/DivisionOverflowTrap.h"

using namespace toyhost;

#if defined(__x86_64__) && defined(__linux__)

namespace {

// idiv with the divisor in a register: quotient and remainder of `dividend` / `divisor`.
std::pair<std::int32_t, std::int32_t> idiv32Register(std::int32_t dividend, std::int32_t divisor) {
    std::int32_t eax = dividend, edx;
    asm volatile("cltd\n\tidivl %2" : "+a"(eax), "=&d"(edx) : "r"(divisor) : "cc");
    return {eax, edx};
}

std::pair<std::int32_t, std::int32_t> idiv32Memory(std::int32_t dividend, std::int32_t divisor) {
    volatile std::int32_t in = divisor;
    std::int32_t eax = dividend, edx;
    asm volatile("cltd\n\tidivl %2" : "+a"(eax), "=&d"(edx) : "m"(in) : "cc");
    return {eax, edx};
}

std::pair<std::int64_t, std::int64_t> idiv64Register(std::int64_t dividend, std::int64_t divisor) {
    std::int64_t rax = dividend, rdx;
    asm volatile("cqto\n\tidivq %2" : "+a"(rax), "=&d"(rdx) : "r"(divisor) : "cc");
    return {rax, rdx};
}

// Whether a forked child running `work` died of it: ended by SIGFPE, or (under a sanitizer,
// whose own SIGFPE handler reports the fault) with SIGABRT or a non-zero status.
template <class Work>
bool childDied(Work work) {
    const pid_t pid = fork();
    if (pid == 0) {
        work();
        _exit(0);
    }
    int status = 0;
    waitpid(pid, &status, 0);
    return WIFSIGNALED(status) ? (WTERMSIG(status) == SIGFPE || WTERMSIG(status) == SIGABRT) : WEXITSTATUS(status) != 0;
}

}  // namespace

TEST(DivisionOverflowTrap, IntMinByMinusOneWrapsWhileATrapLives) {
    const long before = DivisionOverflowTrap::emulated();
    const DivisionOverflowTrap trap;
    EXPECT_EQ(idiv32Register(INT32_MIN, -1), std::make_pair(INT32_MAX, 0));
    EXPECT_EQ(idiv32Memory(INT32_MIN, -1), std::make_pair(INT32_MAX, 0));
    EXPECT_EQ(idiv64Register(INT64_MIN, -1), std::make_pair(INT64_MAX, std::int64_t{0}));
    EXPECT_EQ(DivisionOverflowTrap::emulated() - before, 3);
    // Ordinary divisions are the CPU's own.
    EXPECT_EQ(idiv32Register(-7, 2), std::make_pair(-3, -1));
    EXPECT_EQ(idiv32Memory(INT32_MIN, 1), std::make_pair(INT32_MIN, 0));
    EXPECT_EQ(DivisionOverflowTrap::emulated() - before, 3);
}

TEST(DivisionOverflowTrap, NestedTrapsAndOtherFaultsKeepTheirMeaning) {
    {
        const DivisionOverflowTrap outer;
        {
            const DivisionOverflowTrap inner;
        }
        EXPECT_EQ(idiv32Register(INT32_MIN, -1).first, INT32_MAX) << "the outer trap still holds";
    }
    EXPECT_TRUE(childDied([] { idiv32Register(INT32_MIN, -1); })) << "no trap: the CPU's fault";
    EXPECT_TRUE(childDied([] {
        const DivisionOverflowTrap trap;
        idiv32Register(1, 0);
    })) << "a division by zero is not emulated";
    EXPECT_FALSE(childDied([] {})) << "the check itself";
}

#else
TEST(DivisionOverflowTrap, NothingToTrapOnThisArchitecture) {
    const DivisionOverflowTrap trap;
    EXPECT_EQ(DivisionOverflowTrap::emulated(), 0);
}
#endif
