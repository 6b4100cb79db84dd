// SPDX-License-Identifier: MIT
// Units and number formatting: SI first, US customary beside it, as in the command's summary.
export const G0 = 9.80665;
export const MPH = 0.44704; // m/s
export const FT = 0.3048; // m
export const LB = 0.45359237; // kg
export const KIP = 4448.2216152605; // N
export const KIP_FT = KIP * FT; // N m (also ft-kip of energy, J)
export const IN = 0.0254; // m
export const KSI = KIP / IN ** 2; // Pa
export const PSF = (LB * G0) / FT ** 2; // Pa (lbf/ft²)
export const LB_FT = LB / FT; // kg/m

export function fmt(v, digits = 3) {
  if (v === null || v === undefined || !Number.isFinite(v)) return '–';
  const a = Math.abs(v);
  if (a !== 0 && (a >= 1e6 || a < 1e-3)) return v.toExponential(2);
  return v.toFixed(digits);
}

// Digits after the point so that v shows about `sig` significant digits (at least 0, at most 3), counted on
// v rounded to them: 9.99999 kip (10 kip written to six digits in newtons) shows as 10.0, not 10.00.
export function fixed(v, sig = 3) {
  if (!Number.isFinite(v) || v === 0) return 1;
  const d = sig - 1 - Math.floor(Math.log10(Math.abs(Number(v.toPrecision(sig)))));
  return Math.max(0, Math.min(3, d));
}

export function grouped(v, digits = 0) {
  return v.toLocaleString('en-US', { minimumFractionDigits: digits, maximumFractionDigits: digits });
}

// "17.9 m/s (40.0 mph)" and friends: [SI text, US text].
export const both = {
  speed: (v) => [`${fmt(v, 1)} m/s`, `${fmt(v / MPH, 1)} mph`],
  length: (v) => [`${fmt(v, 2)} m`, `${fmt(v / FT, 1)} ft`],
  force: (v) => [`${fmt(v / 1e3, fixed(v / 1e3))} kN`, `${fmt(v / KIP, fixed(v / KIP))} kip`],
  moment: (v) => [`${fmt(v / 1e3, fixed(v / 1e3))} kN·m`, `${fmt(v / KIP_FT, fixed(v / KIP_FT))} kip·ft`],
  energy: (v) => [`${fmt(v / 1e3, 1)} kJ`, `${fmt(v / KIP_FT, 0)} ft·kip`],
  mass: (v) => [`${grouped(v)} kg`, `${grouped(v / LB)} lb`],
  angle: (v) => [`${fmt((v * 180) / Math.PI, 1)}°`, null],
  diameter: (v) => [`${fmt(v * 1e3, fixed(v * 1e3))} mm`, `${fmt(v / IN, fixed(v / IN))} in`],
  area: (v) => [`${fmt(v * 1e6, fixed(v * 1e6))} mm²`, `${fmt(v / IN ** 2, fixed(v / IN ** 2))} in²`],
  sectionModulus: (v) => [`${fmt(v * 1e6, fixed(v * 1e6))} cm³`, `${fmt(v / IN ** 3, fixed(v / IN ** 3))} in³`],
  inertia: (v) => [`${fmt(v * 1e8, fixed(v * 1e8))} cm⁴`, `${fmt(v / IN ** 4, fixed(v / IN ** 4))} in⁴`],
  stress: (v) => [`${fmt(v / 1e6, fixed(v / 1e6))} MPa`, `${fmt(v / KSI, fixed(v / KSI))} ksi`],
  pressure: (v) => [`${fmt(v / 1e3, fixed(v / 1e3))} kPa`, `${fmt(v / PSF, fixed(v / PSF))} psf`],
  massPerLength: (v) => [`${fmt(v, fixed(v))} kg/m`, `${fmt(v / LB_FT, fixed(v / LB_FT))} lb/ft`],
  pressureGradient: (v) => [`${fmt(v / 1e3, fixed(v / 1e3))} kPa/m`, `${fmt(v / (PSF / FT), fixed(v / (PSF / FT)))} psf/ft`],
};

export function pair(kind, v) {
  const [si, us] = both[kind](v);
  return us ? `${si} (${us})` : si;
}

// A run's time as the command prints it (src/io/out/numtext.h, cs_time_text): at least 3 decimals and as
// many more, up to 6, as show it exactly (its times are whole numbers of steps, summed with round-off).
export function seconds(t) {
  if (t === null || t === undefined || !Number.isFinite(t)) return `${fmt(t)} s`;
  let d = 3;
  while (d < 6 && Math.abs(t * 10 ** d - Math.round(t * 10 ** d)) > 1e-9 * 10 ** d) d++;
  return `${t.toFixed(d)} s`;
}
