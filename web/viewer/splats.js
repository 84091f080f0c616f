// The Gaussians as a Spark SplatMesh built from the server's arrays, and their per-query colours.
import { ExtSplats, RgbaArray, SplatMesh, utils } from "@sparkjsdev/spark";
import { heat } from "./colormap.js";

const STRIDE = 14; // x y z, sx sy sz, qw qx qy qz, opacity, r g b
const MIN_SCALE = 1e-8; // Spark stores log(scale): keep it finite
const HEAT_WEIGHT = 0.8; // how strongly the heat colour covers a selected splat's own colour
const LUT_SIZE = 256;

const toByte = (v) => Math.round(255 * Math.min(1, Math.max(0, v)));

export class Splats {
  constructor(records) {
    const count = records.length / STRIDE;
    this.count = count;
    // ExtSplats keeps centres in float32; PackedSplats' float16 centres are too coarse for a city
    // scene far from the origin.
    const capacity = utils.computeMaxSplats(count);
    const ext = [new Uint32Array(capacity * 4), new Uint32Array(capacity * 4)];
    // Per splat RGBA8 colour override (Spark's SplatMesh.splatRgba): a recolour rewrites and
    // uploads 4 bytes per splat instead of rebuilding the splats.
    this.rgba = new RgbaArray();
    this.rgba.ensureCapacity(count);
    this.rgba.count = count;
    this.base = new Uint8Array(count * 4); // own colour + opacity, restored by clear()
    const d = records;
    for (let i = 0, o = 0; i < count; i++, o += STRIDE) {
      const scale = (k) => Math.max(d[o + k], MIN_SCALE);
      // Spark takes the quaternion as x y z w; the server sends w x y z.
      utils.encodeExtSplat(ext, i, d[o], d[o + 1], d[o + 2], scale(3), scale(4), scale(5),
        d[o + 7], d[o + 8], d[o + 9], d[o + 6], d[o + 10], d[o + 11], d[o + 12], d[o + 13]);
      this.base[i * 4] = toByte(d[o + 11]);
      this.base[i * 4 + 1] = toByte(d[o + 12]);
      this.base[i * 4 + 2] = toByte(d[o + 13]);
      this.base[i * 4 + 3] = toByte(d[o + 10]);
    }
    this.mesh = new SplatMesh({ extSplats: new ExtSplats({ extArrays: ext, numSplats: count }) });
    this.mesh.splatRgba = this.rgba;
    this.mesh.updateGenerator();
    this.lut = Array.from({ length: LUT_SIZE }, (_, k) => heat(k / (LUT_SIZE - 1)));
    this.clear();
  }

  clear() {
    this.rgba.array.set(this.base);
    this.upload();
  }

  // Splats scoring >= threshold take the heat colour of (score - threshold) / (max - threshold),
  // mixed over their own colour; the others keep theirs. Returns how many were highlighted.
  highlight(scores, threshold) {
    let max = threshold;
    for (const s of scores) if (s > max) max = s;
    const span = max > threshold ? max - threshold : 1;
    const out = this.rgba.array;
    out.set(this.base);
    let selected = 0;
    for (let i = 0; i < this.count; i++) {
      if (!(scores[i] >= threshold)) continue; // NaN scores stay unhighlighted too
      const hot = this.lut[Math.round(((scores[i] - threshold) / span) * (LUT_SIZE - 1))];
      for (let c = 0; c < 3; c++) {
        out[i * 4 + c] = HEAT_WEIGHT * hot[c] + (1 - HEAT_WEIGHT) * this.base[i * 4 + c];
      }
      selected++;
    }
    this.upload();
    return { selected, max };
  }

  upload() {
    this.rgba.needsUpdate = true;
    this.mesh.updateVersion(); // makes Spark regenerate the splats with the new colours
  }
}
