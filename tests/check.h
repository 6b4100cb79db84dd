/* SPDX-License-Identifier: MIT */
/* Test helpers on top of cmocka: floating-point comparisons with a stated tolerance. */
#ifndef CS_TEST_CHECK_H
#define CS_TEST_CHECK_H

#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include <cmocka.h>

#define M_PI_2_VALUE 1.57079632679489661923

/* |a - b| <= tol * |b| */
#define CHECK_REL(a, b, tol)                                                                                 \
    do {                                                                                                     \
        double a_ = (a), b_ = (b);                                                                           \
        if (!(fabs(a_ - b_) <= (tol)*fabs(b_)))                                                              \
            fail_msg("%s = %.10g, expected %.10g within %g relative", #a, a_, b_, (double)(tol));            \
    } while (0)

/* |a - b| <= tol */
#define CHECK_ABS(a, b, tol)                                                                                 \
    do {                                                                                                     \
        double a_ = (a), b_ = (b);                                                                           \
        if (!(fabs(a_ - b_) <= (tol)))                                                                       \
            fail_msg("%s = %.10g, expected %.10g within %g", #a, a_, b_, (double)(tol));                     \
    } while (0)

#endif
