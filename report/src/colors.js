// SPDX-License-Identifier: MIT
// The tension colour map of the PNG figures (cs_plot_colormap in src/io/out/plot.c): blue, cyan, green,
// orange, red for 0 to 1.
const STOPS = [
  [0.23, 0.3, 0.75],
  [0.2, 0.6, 0.8],
  [0.45, 0.72, 0.3],
  [0.95, 0.65, 0.1],
  [0.78, 0.08, 0.1],
];

export function colormap(f) {
  f = Number.isFinite(f) ? Math.min(1, Math.max(0, f)) : 0;
  const u = f * 4;
  const k = u >= 4 ? 3 : Math.floor(u);
  const t = u - k;
  const [a, b] = [STOPS[k], STOPS[k + 1]];
  const c = a.map((v, i) => Math.round(255 * (v + t * (b[i] - v))));
  return `rgb(${c[0]}, ${c[1]}, ${c[2]})`;
}

// A CSS gradient of the map, for the colour bar.
export function gradient() {
  const stops = [];
  for (let k = 0; k <= 10; k++) stops.push(`${colormap(k / 10)} ${k * 10}%`);
  return `linear-gradient(to right, ${stops.join(', ')})`;
}
