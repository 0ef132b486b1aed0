// The prescription editor's columns: how each cell shows its row's value (as lens designers read
// them: radii and thicknesses to 4 decimals, nd to 5, Vd to 2, aspheric terms in exponent form),
// how typed text is checked (the reason when it is not acceptable), and what it changes in the row.
// Rows are the service's JSON rows (server/routes/PrescriptionRoutes.cpp): gap is the thickness after the
// surface; a catalog glass by name (index 0: the catalog's nd), a model glass by index and abbe.

const ASPHERIC_TERMS = 8;

// The catalog glasses, keyed as the service matches names: case, spaces, underscores and hyphens
// do not matter, and the maker's prefix may be left out ("BK7" for N-BK7).
const glasses = new Map();
const glassKey = (name) => name.toUpperCase().replace(/[\s_-]/g, "");

// The list is in the service's search order: a name's first glass is the one the service takes.
export function setGlassCatalog(list) {
  glasses.clear();
  for (const g of list) {
    if (!glasses.has(glassKey(g.name))) glasses.set(glassKey(g.name), g);
    const dash = g.name.indexOf("-");
    if (dash > 0 && !glasses.has(glassKey(g.name.slice(dash + 1)))) glasses.set(glassKey(g.name.slice(dash + 1)), g);
  }
}

export const catalogGlass = (name) => (name ? glasses.get(glassKey(name)) : undefined);

function number(text, what) {
  const t = text.trim().replace(",", ".");
  const v = Number(t);
  if (t === "" || !Number.isFinite(v)) return { error: `${what} must be a finite number` };
  return { value: v };
}

const fixed = (v, digits) => (Math.abs(v) >= 1e5 || (v !== 0 && Math.abs(v) < Math.pow(10, -digits)) ? v.toExponential(4) : v.toFixed(digits));
const exponent = (v) => (v === 0 ? "0" : v.toExponential(4).replace(/e([+-])(\d)$/, "e$10$2"));
const isModelGlass = (row) => !row.glass && !row.mirror && row.index > 1;

// Each column: key, heading, title (the header's tooltip), show(row) for the cell, exact(row) for
// a cell being edited (every digit), read(text, row) -> { value } | { error }, and apply(row, value).
export const COLUMNS = [
  {
    key: "radius", heading: "radius", title: "radius of curvature, mm (flat: 0 or 'flat'); positive: centre on the film side",
    show: (r) => (r.radius === 0 ? "flat" : fixed(r.radius, 4)),
    exact: (r) => (r.radius === 0 ? "flat" : String(r.radius)),
    read: (t) => (/^\s*(flat|inf(inity)?|∞)\s*$/i.test(t) ? { value: 0 } : number(t, "the radius")),
    apply: (r, v) => ({ ...r, radius: v }),
  },
  {
    key: "gap", heading: "thickness", title: "thickness to the next surface, mm (negative only after a mirror)",
    show: (r) => fixed(r.gap, 4), exact: (r) => String(r.gap),
    read: (t) => number(t, "the thickness"),
    apply: (r, v) => ({ ...r, gap: v }),
  },
  {
    key: "glass", heading: "glass", title: "a catalog glass (N-BK7, SF2), nd/Vd for a model glass, MIRROR, or empty for air",
    show: (r) => (r.mirror ? "MIRROR" : r.glass), exact: (r) => (r.mirror ? "MIRROR" : r.glass),
    read: (t) => {
      const name = t.trim();
      if (name === "") return { value: { glass: "" } };
      if (/^mirror$/i.test(name)) return { value: { mirror: true } };
      const model = name.match(/^([0-9.]+)\s*\/\s*([0-9.]+)$/);
      if (model) {
        const [nd, vd] = [Number(model[1]), Number(model[2])];
        if (!(nd > 1) || !(vd > 0)) return { error: "a model glass is nd/Vd with nd > 1 and Vd > 0" };
        return { value: { index: nd, abbe: vd } };
      }
      if (/\s/.test(name)) return { error: "a glass name has no spaces" };
      if (glasses.size && !catalogGlass(name)) return { error: `no catalog glass is called '${name}'` };
      return { value: { glass: name } };
    },
    // Air keeps a table's N 1 (or 0); a catalog glass's nd is the catalog's (0).
    // The row's own catalog (Code V's N-BK7_SCHOTT) stays with its glass only.
    apply: (r, v) => ({ ...r, glass: v.glass || "", glass_catalog: v.glass && v.glass === r.glass ? r.glass_catalog : "", mirror: !!v.mirror,
                        index: v.index || (r.index === 1 && !v.glass ? 1 : 0), abbe: v.abbe || 0 }),
  },
  {
    key: "index", heading: "nd", title: "refractive index at the d line (empty or 1: air); typing one makes a model glass",
    show: (r) => { const g = catalogGlass(r.glass); return g ? g.nd.toFixed(5) : r.index > 1 ? r.index.toFixed(5) : ""; },
    exact: (r) => { const g = catalogGlass(r.glass); return g ? String(g.nd) : r.index > 1 ? String(r.index) : ""; },
    read: (t) => {
      if (t.trim() === "" || t.trim() === "1") return { value: 0 };
      const n = number(t, "nd");
      return n.error || n.value >= 1 ? n : { error: "nd must be at least 1 (empty for air)" };
    },
    // A catalog glass given another nd becomes a model glass that keeps the catalog's Vd.
    apply: (r, v) => ({ ...r, index: v, abbe: v > 1 ? (catalogGlass(r.glass) || {}).vd || r.abbe : 0, glass: "", glass_catalog: "", mirror: false }),
    derived: (r) => !!catalogGlass(r.glass),
  },
  {
    key: "abbe", heading: "Vd", title: "Abbe number (empty: no dispersion); needs nd > 1",
    show: (r) => { const g = catalogGlass(r.glass); return g ? (g.vd ? g.vd.toFixed(2) : "") : r.abbe > 0 ? r.abbe.toFixed(2) : ""; },
    exact: (r) => { const g = catalogGlass(r.glass); return g ? String(g.vd || "") : r.abbe > 0 ? String(r.abbe) : ""; },
    read: (t, r) => {
      if (t.trim() === "") return { value: 0 };
      const n = number(t, "Vd");
      if (n.error) return n;
      if (!(n.value > 0)) return { error: "Vd must be positive (empty: no dispersion)" };
      if (!isModelGlass(r) && !catalogGlass(r.glass)) return { error: "a Vd needs a glass: give nd first" };
      return n;
    },
    apply: (r, v) => { const g = catalogGlass(r.glass); return { ...r, abbe: v, index: g ? g.nd : r.index, glass: "", glass_catalog: "" }; },
    derived: (r) => !!catalogGlass(r.glass),
  },
  {
    key: "diameter", heading: "diameter", title: "clear aperture diameter, mm ('auto': derived from the design's aperture and fields)",
    show: (r) => (r.automatic_diameter ? "auto" : fixed(r.diameter, 3)), exact: (r) => (r.automatic_diameter ? "auto" : String(r.diameter)),
    read: (t) => {
      if (/^\s*auto\s*$/i.test(t)) return { value: "auto" };
      const n = number(t, "the diameter");
      return n.error || n.value > 0 ? n : { error: "the diameter must be positive (or auto)" };
    },
    // An automatic diameter has no shape of its own; a typed one is the row's own.
    apply: (r, v) => (v === "auto" ? { ...r, diameter: 0, automatic_diameter: true, clear_aperture: null } : { ...r, diameter: v, automatic_diameter: false }),
  },
  {
    key: "conic", heading: "conic", title: "conic constant k (0 sphere, -1 paraboloid)",
    show: (r) => (r.conic === 0 ? "0" : fixed(r.conic, 4)), exact: (r) => String(r.conic),
    read: (t) => (t.trim() === "" ? { value: 0 } : number(t, "the conic constant")),
    apply: (r, v) => ({ ...r, conic: v }),
  },
  {
    key: "aspheric", heading: "aspheric r², r⁴, … r¹⁶", title: "even-asphere coefficients of r^2 .. r^16, separated by spaces",
    show: (r) => trimTerms(r.aspheric).map(exponent).join(" "),
    exact: (r) => trimTerms(r.aspheric).map(String).join(" "),
    read: (t) => {
      const parts = t.trim() === "" ? [] : t.trim().split(/[\s;]+/);
      if (parts.length > ASPHERIC_TERMS) return { error: `at most ${ASPHERIC_TERMS} terms (r² to r¹⁶)` };
      const terms = [];
      for (const [k, p] of parts.entries()) {
        const n = number(p, `term ${k + 1}`);
        if (n.error) return n;
        terms.push(n.value);
      }
      while (terms.length < ASPHERIC_TERMS) terms.push(0);
      return { value: terms };
    },
    apply: (r, v) => ({ ...r, aspheric: v }),
  },
  {
    key: "coating", heading: "coating",
    title: "none, a material's quarter wave (MgF2, MgF2@550) or a stack (MgF2+ZrO2:2q); empty: the default, MgF2 between air and glass",
    show: (r) => r.coating || "default", exact: (r) => r.coating || "",
    read: (t) => (/\s/.test(t.trim()) ? { error: "a coating is written without spaces (MgF2+ZrO2:2q)" } : { value: t.trim() }),
    apply: (r, v) => ({ ...r, coating: v }),
  },
];

function trimTerms(terms) {
  const t = [...(terms || [])];
  while (t.length && t[t.length - 1] === 0) t.pop();
  return t;
}

// A new surface after `row`: flat, in air, 1 mm on, as wide as its neighbour.
export const newRow = (row) => ({ radius: 0, gap: 1, index: 0, diameter: row && row.diameter > 0 ? row.diameter : 10, stop: false,
  glass: "", glass_catalog: "", abbe: 0, conic: 0, aspheric: new Array(ASPHERIC_TERMS).fill(0), mirror: false, obscuration_diameter: 0,
  coating: "", name: "", kind: "even asphere", form_terms: [], normalisation_radius: 0, clear_aperture: null, obscuration: null,
  frame: null, coordinate_break: false, automatic_diameter: false });

// What a row keeps that the table's columns do not show (a decentre or tilt, a coordinate break, a
// surface form, a shaped aperture, a name), as words for its surface number.
export function keptFeatures(r) {
  const kept = [];
  if (r.coordinate_break) kept.push("coordinate break");
  else if (r.frame) kept.push(`decentre and tilt (${r.frame.mode})`);
  if (r.kind && r.kind !== "even asphere") kept.push(`${r.kind} surface`);
  if (r.clear_aperture) kept.push(`${r.clear_aperture.shape} clear aperture`);
  if (r.obscuration) kept.push(`${r.obscuration.shape} obscuration`);
  if (r.name) kept.push(`"${r.name}"`);
  return kept;
}

// Whether only a .zmx can hold the lens: a lens table has no conic, aspheric terms, mirror,
// obscuration or automatic diameter, none of the rows' kept features, and no field list, aperture,
// wavelengths, object distance or image tilt of the design.
export const needsZemax = (lens) => !!(lens.rows.some((r) => r.conic !== 0 || r.mirror || r.obscuration_diameter > 0 ||
    (r.aspheric || []).some((a) => a !== 0) || r.automatic_diameter || keptFeatures(r).length) ||
  (lens.fields && lens.fields.points.length) || (lens.wavelengths_nm || []).length || lens.object_distance != null ||
  lens.entrance_pupil_diameter != null || lens.f_number != null || lens.object_numerical_aperture != null || lens.image_frame);
