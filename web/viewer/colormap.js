// Heat ramp for query scores: a polynomial fit of the Turbo colormap, the ramp the C++ side uses
// for its relevancy maps (OpenCV COLORMAP_TURBO), so the viewer and the PNG maps read alike.

// Only the part from blue to red: Turbo's dark ends barely stand out over dark splats.
const LOW = 0.2;
const HIGH = 0.95;

function turbo(x) {
  const r = 0.13572138 + x * (4.6153926 + x * (-42.66032258 + x * (132.13108234 + x * (-152.94239396 + x * 59.28637943))));
  const g = 0.09140261 + x * (2.19418839 + x * (4.84296658 + x * (-14.18503333 + x * (4.27729857 + x * 2.82956604))));
  const b = 0.1066733 + x * (12.64194608 + x * (-60.58204836 + x * (110.36276771 + x * (-89.90310912 + x * 27.34824973))));
  return [r, g, b].map((v) => Math.round(255 * Math.min(1, Math.max(0, v))));
}

// t in [0, 1] (threshold .. max score) -> [r, g, b] bytes.
export function heat(t) {
  return turbo(LOW + (HIGH - LOW) * Math.min(1, Math.max(0, t)));
}

// A CSS gradient of the same ramp, for the on-screen legend.
export function heatGradient() {
  const stops = [0, 0.25, 0.5, 0.75, 1].map((t) => `rgb(${heat(t).join(",")}) ${t * 100}%`);
  return `linear-gradient(to right, ${stops.join(", ")})`;
}
