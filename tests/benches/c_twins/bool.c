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

/* b4 turns TRUE in the first round (b2 stays FALSE throughout), so a twin that does nothing
 * fails the check. */
static long long twin_check(void)
{
    return m.b4;
}

#include "timing.h"
