/* The C twin of the `dint` workload: 1,000 DINT statements, the four of INT_STATEMENTS in turn. */
#include "program.h"

static void twin_cycle(void)
{
    for (int round = 0; round < 250; round++) {
        m.i3 = dint_add(m.i1, m.i2);
        m.i2 = dint_sub(m.i3, 7);
        m.i1 = dint_add(m.i2, m.i3);
        m.i3 = dint_sub(m.i3, m.i1);
    }
}

static long long twin_check(void)
{
    return m.i3;
}

#include "timing.h"
