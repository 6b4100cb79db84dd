// Units and number formatting: SI first, US customary beside it, as in the command's summary.
export const G0 = 9.80665;
export const MPH = 0.44704; // m/s
export const FT = 0.3048; // m
export const LB = 0.45359237; // kg
export const KIP = 4448.2216152605; // N
export const KIP_FT = KIP * FT; // N m (also ft-kip of energy, J)

export function fmt(v, digits = 3) {
  if (v === null || v === undefined || !Number.isFinite(v)) return '–';
  const a = Math.abs(v);
  if (a !== 0 && (a >= 1e6 || a < 1e-3)) return v.toExponential(2);
  return v.toFixed(digits);
}

// Digits after the point so that v shows about `sig` significant digits (at least 0, at most 3).
export function fixed(v, sig = 3) {
  if (!Number.isFinite(v) || v === 0) return 1;
  const d = sig - 1 - Math.floor(Math.log10(Math.abs(v)));
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
};

export function pair(kind, v) {
  const [si, us] = both[kind](v);
  return us ? `${si} (${us})` : si;
}

export function seconds(t) {
  return `${fmt(t, 3)} s`;
}
