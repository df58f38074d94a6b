/* The C twin of the `bool` workload: 1,000 BOOL statements, the four of BOOL_STATEMENTS in turn. */
#include "program.h"

static void twin_cycle(void)
{
    for (int round = 0; round < 250; round++) {
        /* ST's AND, OR and XOR evaluate both operands: the bitwise operators, not && and ||. */
        m.b3 = m.b1 & !m.b2;
        m.b4 = m.b3 | m.b2;
        m.b5 = m.b4 ^ m.b1;
        m.b2 = m.b5 & m.b3;
    }
}

static long long twin_check(void)
{
    return m.b2;
}

#include "timing.h"
