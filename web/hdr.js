// Linear HDR pixels on the page: exposure scaling as the report does it (4N²/π times 2^stops),
// sRGB encoding through a table (fast enough to re-map 1024x1024 pixels per input event), the
// exposure that fits an image's 99th percentile, and the difference of two images.
import { authorizedFetch } from "./api.js";

// The report's normalisation: the camera weight averages the exit pupil's solid angle, about
// π/(4N²) of the scene radiance, so scaling by its inverse shows every f-number at scene brightness.
export const normalisation = (fstop) => (fstop > 0 ? (4 * fstop * fstop) / Math.PI : 1);

const TABLE_SIZE = 4096;
const srgbTable = new Uint8ClampedArray(TABLE_SIZE + 1);
for (let i = 0; i <= TABLE_SIZE; i++) {
  const c = i / TABLE_SIZE;
  srgbTable[i] = Math.round(255 * (c <= 0.0031308 ? 12.92 * c : 1.055 * Math.pow(c, 1 / 2.4) - 0.055));
}
const srgbToLinear = new Float32Array(256);
for (let i = 0; i < 256; i++) {
  const s = i / 255;
  srgbToLinear[i] = s <= 0.04045 ? s / 12.92 : Math.pow((s + 0.055) / 1.055, 2.4);
}

// A render's pixels: { width, height, rgb: Float32Array (linear, top row first), fstop }.
export async function fetchPixels(url) {
  const response = await authorizedFetch(url);
  if (!response.ok) {
    const body = await response.json().catch(() => ({}));
    throw new Error(body.error || `${response.status} ${response.statusText}`);
  }
  const width = Number(response.headers.get("X-Image-Width"));
  const height = Number(response.headers.get("X-Image-Height"));
  const fstop = Number(response.headers.get("X-Image-Fstop")) || 0;
  const rgb = new Float32Array(await response.arrayBuffer());
  if (rgb.length !== width * height * 3) throw new Error("the pixel data does not match its size");
  return { width, height, rgb, fstop };
}

// Writes the image, scaled by `scale` and sRGB-encoded, into RGBA bytes.
export function exposeInto(rgba, image, scale) {
  const { rgb } = image;
  const k = scale * TABLE_SIZE;
  for (let i = 0, j = 0; i < rgb.length; i += 3, j += 4) {
    for (let c = 0; c < 3; c++) {
      const t = rgb[i + c] * k;
      rgba[j + c] = srgbTable[t >= TABLE_SIZE ? TABLE_SIZE : t > 0 ? (t + 0.5) | 0 : 0];
    }
    rgba[j + 3] = 255;
  }
}

// Scales an 8-bit sRGB picture (a preview PNG written at exposure 1) in place.
export function exposeSrgbBytes(rgba, scale) {
  const k = scale * TABLE_SIZE;
  for (let j = 0; j < rgba.length; j += 4) {
    for (let c = 0; c < 3; c++) {
      const t = srgbToLinear[rgba[j + c]] * k;
      rgba[j + c] = srgbTable[t >= TABLE_SIZE ? TABLE_SIZE : (t + 0.5) | 0];
    }
  }
}

// The 99th percentile of the pixels' brightest channel (a sample of at most 65536 pixels).
export function percentile99(image) {
  const pixels = image.width * image.height;
  const step = Math.max(1, Math.floor(pixels / 65536));
  const values = new Float32Array(Math.ceil(pixels / step));
  let n = 0;
  for (let p = 0; p < pixels; p += step) {
    const i = 3 * p;
    values[n++] = Math.max(image.rgb[i], image.rgb[i + 1], image.rgb[i + 2]);
  }
  const sorted = values.subarray(0, n).sort();
  return sorted[Math.min(n - 1, Math.floor(0.99 * n))];
}

// |a·sa − b·sb| per channel (the two at their own normalisation, so in the units shown), its
// root-mean-square over all channels and the pixel whose mean channel difference is largest.
export function difference(a, b, sa, sb) {
  const rgb = new Float32Array(a.rgb.length);
  let squares = 0, worst = -1, worstAt = 0;
  for (let i = 0; i < rgb.length; i += 3) {
    let sum = 0;
    for (let c = 0; c < 3; c++) {
      const d = Math.abs(a.rgb[i + c] * sa - b.rgb[i + c] * sb);
      rgb[i + c] = d;
      squares += d * d;
      sum += d;
    }
    if (sum > worst) { worst = sum; worstAt = i / 3; }
  }
  return {
    image: { width: a.width, height: a.height, rgb, fstop: 0 },
    rmse: Math.sqrt(squares / rgb.length),
    worst: { x: worstAt % a.width, y: Math.floor(worstAt / a.width), value: worst / 3 },
  };
}

// The difference's colour scale: black, violet, orange, yellow, white from 0 to 1.
export const DIFFERENCE_STOPS = [[0, 0, 0], [87, 16, 110], [228, 90, 49], [250, 200, 40], [255, 255, 255]];
const rampTable = new Uint8ClampedArray((TABLE_SIZE + 1) * 3);
for (let i = 0; i <= TABLE_SIZE; i++) {
  const x = (i / TABLE_SIZE) * (DIFFERENCE_STOPS.length - 1);
  const k = Math.min(Math.floor(x), DIFFERENCE_STOPS.length - 2);
  const f = x - k;
  for (let c = 0; c < 3; c++) rampTable[3 * i + c] = DIFFERENCE_STOPS[k][c] * (1 - f) + DIFFERENCE_STOPS[k + 1][c] * f;
}

// Writes the mean channel difference, scaled by `scale`, through the colour scale.
export function rampInto(rgba, image, scale) {
  const { rgb } = image;
  const k = (scale * TABLE_SIZE) / 3;
  for (let i = 0, j = 0; i < rgb.length; i += 3, j += 4) {
    const t = (rgb[i] + rgb[i + 1] + rgb[i + 2]) * k;
    const r = 3 * (t >= TABLE_SIZE ? TABLE_SIZE : t > 0 ? (t + 0.5) | 0 : 0);
    rgba[j] = rampTable[r];
    rgba[j + 1] = rampTable[r + 1];
    rgba[j + 2] = rampTable[r + 2];
    rgba[j + 3] = 255;
  }
}
