/* The C twin of the `real` workload: 1,000 REAL statements, the four of REAL_STATEMENTS in turn. */
#include <string.h>

#include "program.h"

static void twin_cycle(void)
{
    for (int round = 0; round < 250; round++) {
        m.r3 = m.r1 * 1.5f + m.r2;
        m.r1 = m.r3 * 0.25f - m.r2;
        m.r2 = m.r1 * 0.5f + 0.125f;
        m.r3 = m.r3 - m.r1;
    }
}

/* The REAL's bits, so that the comparison is exact. */
static long long twin_check(void)
{
    uint32_t bits;
    memcpy(&bits, &m.r3, sizeof bits);
    return bits;
}

#include "timing.h"
