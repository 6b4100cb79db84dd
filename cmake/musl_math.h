/* SPDX-License-Identifier: MIT */
/* Force-included in each of musl's maths sources compiled into the engine with CS_MATH=musl
 * (CMakeLists.txt): the C library's <math.h> first, then musl's internal kernel names moved out of the
 * way of glibc's own declarations of the same names, and musl's `hidden` (its internal linkage). */
#include <math.h>
#define __sin cs_musl_ksin
#define __cos cs_musl_kcos
#define __tan cs_musl_ktan
#define __sinl cs_musl_ksinl
#define __cosl cs_musl_kcosl
#define __tanl cs_musl_ktanl
#define __rem_pio2 cs_musl_rem_pio2
#define __rem_pio2_large cs_musl_rem_pio2_large
#define __expo2 cs_musl_expo2
#define hidden __attribute__((visibility("hidden")))
