// SVG elements for the page's own plots (ghosts.js, design.js).
const SVG = "http://www.w3.org/2000/svg";

export function svg(name, attributes, text) {
  const e = document.createElementNS(SVG, name);
  for (const [k, v] of Object.entries(attributes)) e.setAttribute(k, v);
  if (text !== undefined) e.textContent = text;
  return e;
}
