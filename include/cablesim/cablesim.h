/* cablesim: progressive-failure simulation of perimeter-security cable barriers. Umbrella header. */
#ifndef CABLESIM_H
#define CABLESIM_H

#define CS_VERSION_STRING "0.1.0"

#include "cablesim/def.h"
#include "cablesim/sim.h"

#endif
