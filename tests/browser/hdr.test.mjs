// The page's HDR arithmetic (web/hdr.js) checked in node against closed forms: the report's
// normalisation, sRGB encoding and decoding through the tables (each with its own threshold), the
// 99th percentile, the difference's RMSE and worst pixel, the colour scale's ends.
// usage: node hdr.test.mjs SOURCE_DIR
import { join } from "node:path";
import { pathToFileURL } from "node:url";

const sourceDir = process.argv[2];
if (!sourceDir) {
  console.error("usage: node hdr.test.mjs SOURCE_DIR");
  process.exit(2);
}
const hdr = await import(pathToFileURL(join(sourceDir, "web", "hdr.js")).href);

function check(condition, message) {
  if (!condition) throw new Error("check failed: " + message);
  console.log("ok -", message);
}

const srgb = (c) => Math.round(255 * (c <= 0.0031308 ? 12.92 * c : 1.055 * Math.pow(c, 1 / 2.4) - 0.055));
const image = (width, height, values) => ({ width, height, rgb: Float32Array.from(values), fstop: 0 });

check(Math.abs(hdr.normalisation(5.6) - (4 * 5.6 * 5.6) / Math.PI) < 1e-12 && hdr.normalisation(0) === 1,
      `normalisation 4N²/π: f/5.6 -> ${hdr.normalisation(5.6).toFixed(4)}, no f-number -> 1`);

// Linear values chosen on the table's grid (multiples of 1/4096) are encoded exactly.
const linear = [0, 0.25, 0.5, 0.75, 1, 2, -1, NaN, 1 / 4096];
const rgba = new Uint8ClampedArray(12 * 4);
hdr.exposeInto(rgba, image(3, 3, linear.flatMap((v) => [v, v, v])), 1);
const got = linear.map((_, i) => rgba[4 * i]);
const want = linear.map((v) => (v > 0 ? srgb(Math.min(v, 1)) : 0));
check(JSON.stringify(got) === JSON.stringify(want), `sRGB encoding: ${got.join(" ")} (over 1 clips, negative and NaN are black)`);
hdr.exposeInto(rgba, image(1, 1, [0.125, 0.125, 0.125]), 4);
check(rgba[0] === srgb(0.5) && rgba[3] === 255, "an exposure scale of 4 (two stops) maps 0.125 to 0.5");

// Between the encoding's threshold (linear 0.0031308) and the decoding's (sRGB 0.04045) each
// direction has its own branch: 41/4096 encodes on the power law, sRGB byte 2 decodes on the line.
hdr.exposeInto(rgba, image(1, 1, [41 / 4096, 41 / 4096, 41 / 4096]), 1);
check(rgba[0] === srgb(41 / 4096), `linear ${(41 / 4096).toFixed(5)} encodes on the power law: ${rgba[0]} (want ${srgb(41 / 4096)})`);
const dark = Uint8ClampedArray.from([2, 2, 2, 255]);
hdr.exposeSrgbBytes(dark, 4);
check(Math.abs(dark[0] - srgb((4 * 2) / 255 / 12.92)) <= 1, `sRGB byte 2 decodes on the line, x4: ${dark[0]} (want ${srgb((4 * 2) / 255 / 12.92)})`);

const bytes = Uint8ClampedArray.from([srgb(0.25), srgb(0.25), srgb(0.25), 255]);
hdr.exposeSrgbBytes(bytes, 2);
check(Math.abs(bytes[0] - srgb(0.5)) <= 1 && bytes[3] === 255, `a preview's sRGB bytes scaled by 2: ${srgb(0.25)} -> ${bytes[0]} (want ${srgb(0.5)})`);

const ramp = Array.from({ length: 1000 }, (_, i) => [i, i / 2, 0]).flat();
const p99 = hdr.percentile99(image(1000, 1, ramp));
check(p99 === 990, `99th percentile of the brightest channel over 0..999: ${p99}`);

const a = image(2, 2, [1, 1, 1, 0, 0, 0, 0.5, 0.5, 0.5, 0.2, 0.2, 0.2]);
const b = image(2, 2, [1, 1, 1, 0, 0, 0, 0.5, 0.5, 0.5, 0.2, 0.2, 0.8]);
const d = hdr.difference(a, b, 1, 1);
check(Math.abs(d.rmse - Math.sqrt((0.6 * 0.6) / 12)) < 1e-6, `difference RMSE ${d.rmse.toFixed(6)} = sqrt(0.36/12)`);
check(d.worst.x === 1 && d.worst.y === 1 && Math.abs(d.worst.value - 0.2) < 1e-6, "the worst pixel is (1, 1) with mean |Δ| 0.2");
const scaled = hdr.difference(a, image(2, 2, [0.5, 0.5, 0.5, 0, 0, 0, 0.25, 0.25, 0.25, 0.1, 0.1, 0.1]), 1, 2);
check(scaled.rmse < 1e-7, "each image at its own normalisation: a = 2·b gives no difference");

const ends = new Uint8ClampedArray(8);
hdr.rampInto(ends, image(2, 1, [0, 0, 0, 5, 5, 5]), 1);
check(JSON.stringify([...ends]) === JSON.stringify([0, 0, 0, 255, 255, 255, 255, 255]), "the colour scale runs from black to white");
console.log("hdr test passed");
