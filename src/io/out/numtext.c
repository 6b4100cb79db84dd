/* SPDX-License-Identifier: MIT */
/* "%.10g" without printf: v = M * 2^E exactly (M below 2^53); its 10 significant digits are the integer
 * nearest v * 10^(9 - X), X its decimal exponent, computed exactly as a quotient of 128-bit integers; then
 * C's rules for %g: style f when -4 <= X < 10, else style e, trailing zeros and a bare point dropped. And a
 * run's times for the text outputs, to the decimals that show them exactly. */
#include "numtext.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

__extension__ typedef unsigned __int128 u128; /* GCC and Clang, on every target they build for */

enum { DIGITS = 10, MAX_POW5 = 27 /* 5^27 < 2^63 */ };

static const uint64_t TEN10 = 10000000000u;

static const uint64_t pow5[MAX_POW5 + 1] = {1u,
                                            5u,
                                            25u,
                                            125u,
                                            625u,
                                            3125u,
                                            15625u,
                                            78125u,
                                            390625u,
                                            1953125u,
                                            9765625u,
                                            48828125u,
                                            244140625u,
                                            1220703125u,
                                            6103515625u,
                                            30517578125u,
                                            152587890625u,
                                            762939453125u,
                                            3814697265625u,
                                            19073486328125u,
                                            95367431640625u,
                                            476837158203125u,
                                            2384185791015625u,
                                            11920928955078125u,
                                            59604644775390625u,
                                            298023223876953125u,
                                            1490116119384765625u,
                                            7450580596923828125u};

/* The integer nearest m * 2^e2 * 10^k = m * 5^k * 2^(e2 + k) (ties to even) into *q, from the exact
 * quotient num / den; 0 if num or den does not fit 126 bits (the caller then uses snprintf). */
static int scaled(uint64_t m, int e2, int k, uint64_t *q) {
    if (k > MAX_POW5 || -k > MAX_POW5) return 0;
    u128 num = m, den = 1;
    if (k >= 0)
        num *= pow5[k];
    else
        den = pow5[-k];
    int s = e2 + k; /* the power of two left */
    if (s >= 0) {
        if (s > 126 || num >> (126 - s)) return 0;
        num <<= s;
    } else {
        if (-s > 126 || den >> (126 + s)) return 0;
        den <<= -s;
    }
    u128 quot = num / den, twice_rem = 2 * (num % den);
    if (quot >= TEN10) { /* the exponent's estimate was one low: no rounding needed to know it */
        *q = TEN10;
        return 1;
    }
    uint64_t r = (uint64_t)quot;
    if (twice_rem > den || (twice_rem == den && (r & 1))) r++;
    *q = r;
    return 1;
}

/* C's exponent text: a sign and at least two digits. */
static char *put_exponent(char *p, int x) {
    *p++ = 'e';
    *p++ = x < 0 ? '-' : '+';
    unsigned u = (unsigned)(x < 0 ? -x : x);
    if (u >= 100) *p++ = (char)('0' + u / 100);
    *p++ = (char)('0' + u / 10 % 10);
    *p++ = (char)('0' + u % 10);
    return p;
}

int cs_g10(double v, char buf[CS_G10_SIZE]) {
    uint64_t bits;
    memcpy(&bits, &v, sizeof bits);
    int bexp = (int)(bits >> 52 & 0x7ff);
    uint64_t frac = bits & (((uint64_t)1 << 52) - 1);
    char *p = buf;
    if (bexp == 0 && frac == 0) { /* zero keeps its sign, as printf's "-0" */
        if (bits >> 63) *p++ = '-';
        *p++ = '0';
        *p = '\0';
        return (int)(p - buf);
    }
    if (bexp == 0 || bexp == 0x7ff) return snprintf(buf, CS_G10_SIZE, "%.10g", v);
    uint64_t m = frac | (uint64_t)1 << 52;
    int e2 = bexp - 1075; /* v = m * 2^e2 */
    /* X from the binary exponent b = floor(log2 |v|): floor(b log10 2) (78913 / 2^18, exact for |b| up to
     * 1650) is X or X - 1 */
    long b = e2 + 52, t = b * 78913;
    int x = (int)(t >= 0 ? t >> 18 : -((-t + (1 << 18) - 1) >> 18));
    uint64_t q;
    if (!scaled(m, e2, DIGITS - 1 - x, &q)) return snprintf(buf, CS_G10_SIZE, "%.10g", v);
    while (q == TEN10) { /* X is larger (the estimate, or rounding up to 10^(X+1)): afresh at x + 1 */
        x++;
        if (!scaled(m, e2, DIGITS - 1 - x, &q)) return snprintf(buf, CS_G10_SIZE, "%.10g", v);
    }
    char d[DIGITS];
    for (int i = DIGITS - 1; i >= 0; i--, q /= 10)
        d[i] = (char)('0' + q % 10);
    int n = DIGITS; /* the significant digits kept: trailing zeros go */
    while (n > 1 && d[n - 1] == '0')
        n--;
    if (bits >> 63) *p++ = '-';
    if (x >= -4 && x < DIGITS) { /* style f */
        if (x >= 0) {
            int whole = x + 1;
            memcpy(p, d, (size_t)whole);
            p += whole;
            if (n > whole) {
                *p++ = '.';
                memcpy(p, d + whole, (size_t)(n - whole));
                p += n - whole;
            }
        } else {
            *p++ = '0';
            *p++ = '.';
            for (int z = 0; z < -x - 1; z++)
                *p++ = '0';
            memcpy(p, d, (size_t)n);
            p += n;
        }
    } else { /* style e */
        *p++ = d[0];
        if (n > 1) {
            *p++ = '.';
            memcpy(p, d + 1, (size_t)(n - 1));
            p += n - 1;
        }
        p = put_exponent(p, x);
    }
    *p = '\0';
    return (int)(p - buf);
}

const char *cs_time_text(double t, char buf[CS_TIME_TEXT_SIZE]) {
    int decimals = 3;
    while (decimals < 6 &&
           fabs(t * pow(10.0, decimals) - nearbyint(t * pow(10.0, decimals))) > 1e-9 * pow(10.0, decimals))
        decimals++;
    snprintf(buf, CS_TIME_TEXT_SIZE, "%.*f", decimals, t);
    return buf;
}
