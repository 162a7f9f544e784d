#!/usr/bin/env node
// The IFC reader of `relight import` (src/import/ifc_model.h runs it): web-ifc (npm, the version
// of importer/package.json) parses the STEP file, places every product and cuts its openings;
// this script writes what relight needs of it as one JSON document.
// Usage: node ifc-extract.mjs MODEL.ifc OUT.json   (exit 0; 3 when web-ifc cannot open the file)
// web-ifc is resolved from this script's folder upward (importer/node_modules), else from each
// NODE_PATH entry.
//
// Output: metres, world coordinates in IFC axes (z up, +y project north), no recentring:
// { schema, units, length_unit_to_m, site, storeys (by elevation), elements: [{ id, class, name,
// long_name, object_type, type_name, type_class, storey, parent, predefined_type,
// is_light_fixture, placement (4×4 column-major), photometry, parts: [{ color [r,g,b,a],
// material_name, positions [x,y,z,…], indices [...] }] }] }.
import fs from 'node:fs';
import path from 'node:path';
import { createRequire } from 'node:module';
import { pathToFileURL } from 'node:url';

async function loadWebIfc() {
  try { return await import('web-ifc'); } catch (e) {
    for (const dir of (process.env.NODE_PATH || '').split(path.delimiter).filter(Boolean)) {
      try {
        const req = createRequire(path.join(path.resolve(dir), 'noop.js'));
        return await import(pathToFileURL(req.resolve('web-ifc')).href);
      } catch { /* try next */ }
    }
    throw new Error('web-ifc is not installed: run scripts/bootstrap.sh (npm ci in importer/)');
  }
}
const W = await loadWebIfc();

const [, , inFile, outFile] = process.argv;
if (!inFile || !outFile) { console.error('usage: node ifc-extract.mjs MODEL.ifc OUT.json'); process.exit(2); }

const tStart = performance.now();
const api = new W.IfcAPI();
await api.Init();
try { api.SetLogLevel(W.LogLevel.LOG_LEVEL_OFF ?? 6); } catch { }
let m = -1;
try {
  m = api.OpenModel(new Uint8Array(fs.readFileSync(inFile)), { COORDINATE_TO_ORIGIN: false });
} catch (e) {
  console.error(String(e?.message ?? e)); // one line: relight import quotes it
  process.exit(3);
}
if (m < 0) { console.error('the model did not open'); process.exit(3); }
const schema = api.GetModelSchema(m);
// web-ifc 0.0.78 bakes a Z-up -> Y-up rotation (three.js convention) into every
// PlacedGeometry.flatTransformation: (x, y, z)_ifc -> (x, z, -y). (SetGeometryTransformation(identity)
// had no effect in 0.0.78.) We undo it per vertex: ifc = (x', -z', y').

// ---------- helpers ----------
const lineCache = new Map();
const L = (id) => { if (id == null) return null; let l = lineCache.get(id); if (!l) { try { l = api.GetLine(m, id); } catch { l = null; } lineCache.set(id, l); } return l; };
const ids = (type) => { try { return [...api.GetLineIDsWithType(m, type, true)]; } catch { return []; } };
const ref = (h) => (h && typeof h === 'object' && 'value' in h && h.type === 5) ? h.value : (typeof h === 'number' ? h : null);
const val = (a) => (a == null ? null : (typeof a === 'object' && 'value' in a ? a.value : a));
const str = (a) => { const v = val(a); return v == null || v === '' ? null : String(v); };
const cls = (id) => api.GetNameFromTypeCode(api.GetLineType(m, id)).toUpperCase();
const arr = (a) => (Array.isArray(a) ? a : a == null ? [] : [a]);

// ---------- units ----------
const PREFIX = { EXA: 1e18, PETA: 1e15, TERA: 1e12, GIGA: 1e9, MEGA: 1e6, KILO: 1e3, HECTO: 1e2, DECA: 10, DECI: 1e-1, CENTI: 1e-2, MILLI: 1e-3, MICRO: 1e-6, NANO: 1e-9, PICO: 1e-12 };
const units = {};
let lengthToM = 1;
function unitInfo(u) {
  const t = cls(u.expressID);
  const kind = val(u.UnitType);
  if (t === 'IFCSIUNIT') { const p = val(u.Prefix); return { kind, name: (p ? p + ' ' : '') + val(u.Name), factor: p ? PREFIX[p] : 1 }; }
  if (t === 'IFCCONVERSIONBASEDUNIT' || t === 'IFCCONVERSIONBASEDUNITWITHOFFSET') {
    const mwu = L(ref(u.ConversionFactor)); const vc = val(mwu?.ValueComponent); const base = L(ref(mwu?.UnitComponent));
    const bf = base ? unitInfo(base).factor : 1;
    return { kind, name: val(u.Name), factor: Number(vc) * bf };
  }
  return { kind, name: t, factor: null };
}
for (const ua of ids(W.IFCUNITASSIGNMENT)) {
  for (const h of arr(L(ua).Units)) {
    const u = L(ref(h)); if (!u || !u.UnitType) continue;
    const info = unitInfo(u); units[info.kind] = { name: info.name, factor: info.factor }; // factor: to the unprefixed SI unit (LENGTHUNIT: to metres)
    if (info.kind === 'LENGTHUNIT' && info.factor) lengthToM = info.factor;
  }
}

// ---------- site / true north ----------
const compound = (c) => { const a = arr(val(c)).map(val).map(Number); if (!a.length) return null; return a[0] + (a[1] || 0) / 60 + (a[2] || 0) / 3600 + (a[3] || 0) / 3.6e9; };
let trueNorth = { deg: 0, source: 'default (no TrueNorth: +Y is north)', vector: null };
for (const cid of ids(W.IFCGEOMETRICREPRESENTATIONCONTEXT)) {
  const c = L(cid);
  if (cls(cid) !== 'IFCGEOMETRICREPRESENTATIONCONTEXT') continue; // subcontexts inherit TrueNorth
  const tn = L(ref(c.TrueNorth)); if (!tn) continue;
  const r = arr(tn.DirectionRatios).map(val).map(Number);
  // Express TN in world XY: if the context WCS is rotated, rotate TN by its RefDirection.
  let [x, y] = r; const wcs = L(ref(c.WorldCoordinateSystem)); const rd = wcs && L(ref(wcs.RefDirection));
  if (rd) { const [ax, ay] = arr(rd.DirectionRatios).map(val).map(Number); const n = Math.hypot(ax, ay) || 1; const cx = ax / n, cy = ay / n; [x, y] = [cx * x - cy * y, cy * x + cx * y]; }
  // angle from project +Y to TN, clockwise positive seen from above (+Z): atan2(x, y)
  trueNorth = { deg: Math.atan2(x, y) * 180 / Math.PI, source: `IfcGeometricRepresentationContext #${cid} (${str(c.ContextType)}).TrueNorth #${tn.expressID} = (${r.join(', ')}); deg = atan2(x, y)`, vector: [x, y] };
  if (str(c.ContextType) === 'Model') break;
}
let mapConversion = null;
try { for (const id of ids(W.IFCMAPCONVERSION)) { const mc = L(id); mapConversion = { eastings: val(mc.Eastings), northings: val(mc.Northings), orthogonal_height: val(mc.OrthogonalHeight), x_axis_abscissa: val(mc.XAxisAbscissa), x_axis_ordinate: val(mc.XAxisOrdinate), scale: val(mc.Scale) }; } } catch { }
const siteIds = ids(W.IFCSITE);
let site = null;
if (siteIds.length) {
  const s = L(siteIds[0]);
  site = {
    id: siteIds[0], name: str(s.Name),
    latitude: compound(s.RefLatitude), longitude: compound(s.RefLongitude),
    elevation_m: s.RefElevation != null ? Number(val(s.RefElevation)) * lengthToM : null,
    true_north_deg: trueNorth.deg, true_north_source: trueNorth.source,
    map_conversion: mapConversion,
  };
}

// ---------- relationships ----------
const containedIn = new Map(), aggParent = new Map(), typeOf = new Map(), materialsOf = new Map(), docsOf = new Map();
for (const id of ids(W.IFCRELCONTAINEDINSPATIALSTRUCTURE)) { const r = L(id); for (const e of arr(r.RelatedElements)) containedIn.set(ref(e), ref(r.RelatingStructure)); }
for (const id of ids(W.IFCRELAGGREGATES)) { const r = L(id); for (const e of arr(r.RelatedObjects)) aggParent.set(ref(e), ref(r.RelatingObject)); }
for (const id of ids(W.IFCRELDEFINESBYTYPE)) { const r = L(id); for (const e of arr(r.RelatedObjects)) typeOf.set(ref(e), ref(r.RelatingType)); }
for (const id of ids(W.IFCRELASSOCIATESMATERIAL)) { const r = L(id); for (const e of arr(r.RelatedObjects)) materialsOf.set(ref(e), ref(r.RelatingMaterial)); }
const docRels = [W.IFCRELASSOCIATESDOCUMENT, W.IFCRELASSOCIATESLIBRARY].filter(Boolean);
for (const t of docRels) for (const id of ids(t)) { const r = L(id); const d = ref(r.RelatingDocument ?? r.RelatingLibrary); for (const e of arr(r.RelatedObjects)) { const k = ref(e); if (!docsOf.has(k)) docsOf.set(k, []); docsOf.get(k).push(d); } }

const storeyIds = new Set(ids(W.IFCBUILDINGSTOREY));
function storeyOf(id) {
  let cur = id;
  for (let i = 0; i < 32 && cur != null; i++) {
    if (storeyIds.has(cur)) return cur;
    cur = containedIn.get(cur) ?? aggParent.get(cur) ?? null;
  }
  return null;
}
function worldZ(plid) { try { return Number(api.GetWorldTransformMatrix(m, plid)[14]) * lengthToM; } catch { return null; } }
const storeys = [...storeyIds].map((id) => {
  const s = L(id); const el = s.Elevation != null ? Number(val(s.Elevation)) * lengthToM : null;
  return { id, name: str(s.Name), long_name: str(s.LongName), elevation: el ?? worldZ(ref(s.ObjectPlacement)), elevation_source: el != null ? 'Elevation' : 'ObjectPlacement z' };
})
  .sort((a, b) => (a.elevation ?? 0) - (b.elevation ?? 0));

// ---------- styles -> material names ----------
const styleName = new Map();       // surface style id -> name
const itemStyles = new Map();      // representation item id -> [surface style id]
function surfaceStylesOf(styledItem) {
  const out = [];
  for (const h of arr(styledItem.Styles)) {
    const s = L(ref(h)); if (!s) continue;
    const c = cls(s.expressID);
    if (c === 'IFCSURFACESTYLE') out.push(s.expressID);
    else if (c === 'IFCPRESENTATIONSTYLEASSIGNMENT') for (const h2 of arr(s.Styles)) { const s2 = L(ref(h2)); if (s2 && cls(s2.expressID) === 'IFCSURFACESTYLE') out.push(s2.expressID); }
  }
  for (const s of out) styleName.set(s, str(L(s).Name));
  return out;
}
for (const id of ids(W.IFCSTYLEDITEM)) {
  const si = L(id); const st = surfaceStylesOf(si); const it = ref(si.Item);
  if (it != null && st.length) itemStyles.set(it, st);
}
const styleMaterial = new Map(); // surface style id -> material name (IfcMaterialDefinitionRepresentation)
for (const id of ids(W.IFCMATERIALDEFINITIONREPRESENTATION)) {
  const r = L(id); const mat = L(ref(r.RepresentedMaterial)); const mname = str(mat?.Name);
  for (const rh of arr(r.Representations)) { const rep = L(ref(rh)); for (const ih of arr(rep?.Items)) { const si = L(ref(ih)); if (si) for (const s of surfaceStylesOf(si)) if (!styleMaterial.has(s)) styleMaterial.set(s, mname); } }
}
// single material name of an element (or its type) if unambiguous
function materialNames(matId) {
  const x = L(matId); if (!x) return [];
  switch (cls(matId)) {
    case 'IFCMATERIAL': return [str(x.Name)];
    case 'IFCMATERIALLIST': return arr(x.Materials).map((h) => str(L(ref(h))?.Name));
    case 'IFCMATERIALLAYERSETUSAGE': return materialNames(ref(x.ForLayerSet));
    case 'IFCMATERIALLAYERSET': return arr(x.MaterialLayers).flatMap((h) => materialNames(ref(L(ref(h))?.Material)));
    case 'IFCMATERIALLAYER': return materialNames(ref(x.Material));
    case 'IFCMATERIALCONSTITUENTSET': return arr(x.MaterialConstituents).flatMap((h) => materialNames(ref(L(ref(h))?.Material)));
    case 'IFCMATERIALPROFILESETUSAGE': return materialNames(ref(x.ForProfileSet));
    case 'IFCMATERIALPROFILESET': return arr(x.MaterialProfiles).flatMap((h) => materialNames(ref(L(ref(h))?.Material)));
    default: return [];
  }
}
function elementMaterial(id) {
  const mid = materialsOf.get(id) ?? materialsOf.get(typeOf.get(id));
  const names = [...new Set(materialNames(mid).filter(Boolean))];
  return names.length === 1 ? names[0] : null;
}
function partMaterialName(geomItemId, elementId) {
  for (const s of itemStyles.get(geomItemId) ?? []) { const mn = styleMaterial.get(s); if (mn) return mn; }
  for (const s of itemStyles.get(geomItemId) ?? []) { const sn = styleName.get(s); if (sn) return sn; }
  return elementMaterial(elementId);
}

// ---------- photometry ----------
function extRefLocation(id) { const r = L(id); if (!r) return null; return str(r.Location) ?? str(r.Identification) ?? str(r.ItemReference) ?? str(r.Name); }
function goniometricFromRepresentation(repHandleList) {
  for (const rh of repHandleList) {
    const rep = L(ref(rh)); if (!rep) continue;
    for (const ih of arr(rep.Items ?? L(ref(rep.MappedRepresentation))?.Items)) {
      const it = L(ref(ih)); if (!it) continue;
      const c = cls(it.expressID);
      if (c === 'IFCLIGHTSOURCEGONIOMETRIC') { const src = ref(it.LightDistributionDataSource); if (src && cls(src) !== 'IFCLIGHTINTENSITYDISTRIBUTION') return extRefLocation(src); return 'embedded:IfcLightIntensityDistribution#' + src; }
      if (c === 'IFCMAPPEDITEM') { const rm = L(ref(it.MappingSource)); const r = goniometricFromRepresentation([rm?.MappedRepresentation]); if (r) return r; }
    }
  }
  return null;
}
function photometryOf(id, prod) {
  const reps = arr(L(ref(prod.Representation))?.Representations);
  let p = goniometricFromRepresentation(reps); if (p) return p;
  const tid = typeOf.get(id);
  if (tid) { const t = L(tid); p = goniometricFromRepresentation(arr(t.RepresentationMaps).map((h) => L(ref(h))?.MappedRepresentation)); if (p) return p; }
  for (const k of [id, tid]) for (const d of docsOf.get(k) ?? []) { const loc = extRefLocation(d); if (loc && /\.(ies|ldt|eul|eulumdat)$/i.test(loc)) return loc; }
  return null;
}

// ---------- geometry ----------
const geom = new Map(); // id -> Map(partKey -> part)
const r6 = (x) => Math.round(x * 1e5) / 1e5;
function onMesh(mesh) {
  const id = mesh.expressID;
  let parts = geom.get(id); if (!parts) { parts = new Map(); geom.set(id, parts); }
  const gs = mesh.geometries;
  for (let i = 0; i < gs.size(); i++) {
    const pg = gs.get(i);
    const g = api.GetGeometry(m, pg.geometryExpressID);
    const v = api.GetVertexArray(g.GetVertexData(), g.GetVertexDataSize());
    const ix = api.GetIndexArray(g.GetIndexData(), g.GetIndexDataSize());
    const c = pg.color; const color = [r6(c.x), r6(c.y), r6(c.z), r6(c.w)];
    const material_name = partMaterialName(pg.geometryExpressID, id);
    const key = color.join(',') + '|' + material_name;
    let part = parts.get(key); if (!part) { part = { color, material_name, positions: [], indices: [] }; parts.set(key, part); }
    const M = pg.flatTransformation; // column-major; includes placement, unit scaling to metres and the Y-up rotation
    const base = part.positions.length / 3;
    for (let k = 0; k < v.length; k += 6) {
      const x = v[k], y = v[k + 1], z = v[k + 2];
      const wx = M[0] * x + M[4] * y + M[8] * z + M[12], wy = M[1] * x + M[5] * y + M[9] * z + M[13], wz = M[2] * x + M[6] * y + M[10] * z + M[14];
      part.positions.push(r6(wx), r6(-wz), r6(wy)); // undo Y-up
    }
    for (let k = 0; k < ix.length; k++) part.indices.push(base + ix[k]);
    g.delete();
  }
}
api.StreamAllMeshes(m, onMesh);                          // skips IfcSpace / IfcOpeningElement by default
api.StreamAllMeshesWithTypes(m, [W.IFCSPACE], onMesh);   // spaces explicitly
const tGeom = performance.now();

// ---------- elements ----------
const isLightFixtureType = (tid) => tid != null && cls(tid) === 'IFCLIGHTFIXTURETYPE';
const mergeIntoParent = new Set(['IFCWINDOW', 'IFCDOOR']); // windows/doors built from aggregated parts (e.g. IfcOpenHouse)
const childrenOf = new Map();
for (const [c, p] of aggParent) { if (!childrenOf.has(p)) childrenOf.set(p, []); childrenOf.get(p).push(c); }
const mergedChildren = new Set();
for (const [p, kids] of childrenOf) {
  if (!mergeIntoParent.has(cls(p))) continue;
  const own = geom.get(p); if (own && [...own.values()].some((x) => x.indices.length)) continue;
  const parts = new Map();
  for (const k of kids) for (const [key, part] of geom.get(k) ?? []) { if (!parts.has(key)) parts.set(key, { ...part, positions: [], indices: [] }); const t = parts.get(key); const b = t.positions.length / 3; t.positions.push(...part.positions); for (const i of part.indices) t.indices.push(b + i); mergedChildren.add(k); }
  if (parts.size) geom.set(p, parts);
}

const elements = [];
for (const [id, parts] of geom) {
  const c = cls(id);
  if (c === 'IFCOPENINGELEMENT' || c === 'IFCOPENINGSTANDARDCASE' || mergedChildren.has(id)) continue;
  const ps = [...parts.values()].filter((p) => p.indices.length);
  if (!ps.length) continue;
  const e = L(id);
  const tid = typeOf.get(id) ?? null;
  const t = tid ? L(tid) : null;
  let placement = null;
  const plid = ref(e.ObjectPlacement);
  if (plid) { try { placement = [...api.GetWorldTransformMatrix(m, plid)].map(Number); placement[12] *= lengthToM; placement[13] *= lengthToM; placement[14] *= lengthToM; } catch { placement = null; } }
  const pre = str(e.PredefinedType) ?? str(t?.PredefinedType);
  const light = c === 'IFCLIGHTFIXTURE' || isLightFixtureType(tid);
  elements.push({
    id, class: c, name: str(e.Name), long_name: str(e.LongName), object_type: str(e.ObjectType),
    type_name: str(t?.Name), type_class: tid ? cls(tid) : null,
    storey: storeyOf(id), parent: aggParent.get(id) ?? null,
    predefined_type: pre, is_light_fixture: light,
    placement: placement ? placement.map(r6) : null,
    photometry: light ? photometryOf(id, e) : null,
    parts: ps,
  });
}
elements.sort((a, b) => a.id - b.id);

const out = { schema, units, length_unit_to_m: lengthToM, site, storeys, elements };
fs.writeFileSync(outFile, JSON.stringify(out));
api.CloseModel(m);
