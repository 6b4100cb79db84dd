/* SPDX-License-Identifier: MIT */
/** @file
 * The US customary units the engineers who use cablesim work in, each as its exact value in SI (NIST SP
 * 811, Appendix B): multiply a value in the unit by it for SI, divide an SI value by it for the unit. The
 * engine is SI throughout; these serve the edges (values written by hand, outputs for people). Model
 * files take any unit udunits2 knows (loader.h). */
#ifndef CABLESIM_UNITS_H
#define CABLESIM_UNITS_H

#define CS_PI 3.14159265358979323846 /**< pi */
#define CS_DEG (CS_PI / 180.0)       /**< degree, rad */
#define CS_IN 0.0254                 /**< inch, m */
#define CS_FT 0.3048                 /**< foot, m */
#define CS_MPH 0.44704               /**< mile per hour, m/s */
#define CS_LB 0.45359237             /**< pound (mass), kg */
#define CS_G0 9.80665                /**< standard gravity, m/s^2: one g of deceleration */
#define CS_LBF 4.4482216152605       /**< pound-force, N */
#define CS_KIP 4448.2216152605       /**< kip (1,000 lbf), N */
#define CS_PSF 47.88025898033584     /**< pound-force per square foot, Pa */
#define CS_KSI 6.894757293168361e6   /**< kip per square inch, Pa */
#define CS_FT_LBF 1.3558179483314004 /**< foot pound-force, J */

#endif
