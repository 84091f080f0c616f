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
    this.own = new Uint8Array(count * 4); // own colour + opacity
    this.base = this.own; // own, or a copy with hidden splats at alpha 0 (hideOutside); restored by clear()
    this.centers = new Float32Array(count * 3);
    this.hidden = null; // Uint8Array, 1 = hidden, or null: none
    this.keep = null; // the box hidden splats lie outside (THREE.Box3), or null
    const d = records;
    for (let i = 0, o = 0; i < count; i++, o += STRIDE) {
      const scale = (k) => Math.max(d[o + k], MIN_SCALE);
      // Spark takes the quaternion as x y z w; the server sends w x y z.
      utils.encodeExtSplat(ext, i, d[o], d[o + 1], d[o + 2], scale(3), scale(4), scale(5),
        d[o + 7], d[o + 8], d[o + 9], d[o + 6], d[o + 10], d[o + 11], d[o + 12], d[o + 13]);
      this.own[i * 4] = toByte(d[o + 11]);
      this.own[i * 4 + 1] = toByte(d[o + 12]);
      this.own[i * 4 + 2] = toByte(d[o + 13]);
      this.own[i * 4 + 3] = toByte(d[o + 10]);
      this.centers.set(d.subarray(o, o + 3), i * 3);
    }
    this.mesh = new SplatMesh({ extSplats: new ExtSplats({ extArrays: ext, numSplats: count }) });
    this.mesh.splatRgba = this.rgba;
    this.mesh.updateGenerator();
    // Spark's raycast reads the splats' own opacity, not the override that hides them: drop the hits
    // outside the kept box, so that a three.js pick never lands on a hidden splat.
    const raycast = this.mesh.raycast.bind(this.mesh);
    this.mesh.raycast = (raycaster, intersects) => {
      const hits = [];
      raycast(raycaster, hits);
      for (const hit of hits) if (!this.keep || this.keep.containsPoint(hit.point)) intersects.push(hit);
    };
    this.lut = Array.from({ length: LUT_SIZE }, (_, k) => heat(k / (LUT_SIZE - 1)));
    this.clear();
  }

  // Hides (alpha 0 in the override) the splats whose centres lie outside `box` (a THREE.Box3), or
  // none for null. A hidden splat is neither drawn nor highlighted nor counted by highlight().
  // Takes effect at the next clear() or highlight(); returns how many are hidden.
  hideOutside(box) {
    this.keep = box;
    if (!box) {
      this.hidden = null;
      this.base = this.own;
      return 0;
    }
    const { min, max } = box;
    const c = this.centers;
    this.hidden = new Uint8Array(this.count);
    this.base = this.own.slice();
    let hidden = 0;
    for (let i = 0; i < this.count; i++) {
      const x = c[3 * i], y = c[3 * i + 1], z = c[3 * i + 2];
      // NaN centres fail every comparison: hidden too.
      if (x >= min.x && x <= max.x && y >= min.y && y <= max.y && z >= min.z && z <= max.z) continue;
      this.hidden[i] = 1;
      this.base[i * 4 + 3] = 0;
      hidden++;
    }
    return hidden;
  }

  clear() {
    this.rgba.array.set(this.base);
    this.upload();
  }

  // Splats scoring >= threshold take the heat colour of (score - threshold) / (max - threshold),
  // mixed over their own colour; the others keep theirs. Hidden splats count for neither the
  // maximum nor the selection. Returns how many were highlighted.
  highlight(scores, threshold) {
    const hidden = this.hidden;
    let max = threshold;
    for (let i = 0; i < this.count; i++) if (scores[i] > max && !hidden?.[i]) max = scores[i];
    const span = max > threshold ? max - threshold : 1;
    const out = this.rgba.array;
    out.set(this.base);
    let selected = 0;
    for (let i = 0; i < this.count; i++) {
      if (!(scores[i] >= threshold) || hidden?.[i]) continue; // NaN scores stay unhighlighted too
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
