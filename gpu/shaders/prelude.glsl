// Shared prelude of every brush pass. The host prepends `#version 430 core` and the defines
// (OCTACLAY_LAYER, LAYER_*, BRUSH_AREA_*, BRUSH_FALLOFF_*) and appends the brush body and main().
// OCTACLAY_LAYER is LAYER_ALL for a body that defines brushLayers(): one pass writes positions,
// diffuse and feature.
#if !defined(LAYER_ALL) // hosts that include the prelude for its helpers only
#define LAYER_ALL 4
#endif

uniform sampler2D u_positions; // RGBA32F: xyz position, w saliency
uniform sampler2D u_layer;     // the layer this pass writes (== u_positions for positions and
                               // LAYER_ALL)
uniform sampler2D u_mask;      // R: 1 = full effect, 0 = blocked (read only if BRUSH_MASK_TEXTURE)
uniform float u_maskFill;      // the mask's value everywhere while it is unpainted
uniform vec4 u_layerFill;      // the written layer's base value (erase modes return to it)
uniform vec4 u_diffuseFill;    // LAYER_ALL: the diffuse and feature layers' base values
uniform vec4 u_featureFill;
uniform float u_falloffCurve[64]; // falloff "curve": values from centre (0) to rim (1)
uniform int u_falloffCurveSize;
uniform int u_size;            // N: the image has (N+1)^2 samples (a torus's or plane's W)
uniform ivec2 u_cells;         // W, H: the image has (W+1) x (H+1) samples (N, N on the ball)
uniform int u_topology;        // 0 octahedral (the default), 1 torus, 2 plane (core::Topology)
// The dab: uniforms for a pass of one dab. A batch of dabs in one pass (OCTACLAY_BATCH: dabs
// whose passes cannot see each other's texels, e.g. a dab's mirror images) gives each rectangle
// its dab (v_dab, from the vertex shader) and sets these as globals from it: loadDab(), first
// in main().
#if defined(OCTACLAY_BATCH)
// The dab's values, flat from the vertex shader (batchedRectsVertexShader, which reads them
// once a vertex): centre, centre normal, drag, stroke delta, stroke direction, the projection's
// direction, right and up (xyz each), then radius, strength, pressure and normal cosine.
flat in vec4 v_dab[9];
flat in ivec4 v_dabTexel; // xy: the centre texel
#define OCTACLAY_DAB_VALUE
#else
#define OCTACLAY_DAB_VALUE uniform
#endif
OCTACLAY_DAB_VALUE vec3 u_centre;
OCTACLAY_DAB_VALUE vec3 u_centreNormal;
OCTACLAY_DAB_VALUE float u_radius;        // object units
OCTACLAY_DAB_VALUE float u_strength;      // fraction of the radius
OCTACLAY_DAB_VALUE float u_pressure;
OCTACLAY_DAB_VALUE float u_normalCosine;  // volume+normal: minimum cos(angle) to the centre normal
OCTACLAY_DAB_VALUE ivec2 u_centreTexel;
OCTACLAY_DAB_VALUE vec3 u_projectionDir;     // splats: projection frame, object space, unit
OCTACLAY_DAB_VALUE vec3 u_projectionRight;
OCTACLAY_DAB_VALUE vec3 u_projectionUp;
OCTACLAY_DAB_VALUE vec3 u_drag;            // API 3: the drag since the stroke began, object units
OCTACLAY_DAB_VALUE vec3 u_strokeDelta;     // its change since the stroke's previous dab
OCTACLAY_DAB_VALUE vec3 u_strokeDirection; // that change's direction, unit (0 before it moved)
void loadDab() {
#if defined(OCTACLAY_BATCH)
  u_centre = v_dab[0].xyz;
  u_centreNormal = v_dab[1].xyz;
  u_drag = v_dab[2].xyz;
  u_strokeDelta = v_dab[3].xyz;
  u_strokeDirection = v_dab[4].xyz;
  u_projectionDir = v_dab[5].xyz;
  u_projectionRight = v_dab[6].xyz;
  u_projectionUp = v_dab[7].xyz;
  u_radius = v_dab[8].x;
  u_strength = v_dab[8].y;
  u_pressure = v_dab[8].z;
  u_normalCosine = v_dab[8].w;
  u_centreTexel = v_dabTexel.xy;
#endif
}
uniform sampler2D u_featureLayer; // the feature layer as it was before this dab (splats)
uniform sampler2D u_diffuseLayer; // the diffuse layer as it was before this dab
uniform sampler2D u_strokeStart; // "stroke_start": the positions when the stroke began
#if defined(BRUSH_MATERIAL)
// The chosen material's maps (repeat-wrapped; nearest texel, bilinear where magnified) and
// scales, object units unless noted.
// Each sampler holds the one mip level this dab's footprint needs: the first pair for the
// projection from the view, the Uv pair through image coordinates (tiles of u_tileSamples).
uniform sampler2D u_materialColour;    // RGBA, alpha = coverage
uniform sampler2D u_materialSurface;   // R height (0.5 = none), G specular, B reflectivity
uniform sampler2D u_materialColourUv;  // the same maps at the uv projection's level
uniform sampler2D u_materialSurfaceUv;
uniform float u_materialLod;   // 0 (each sampler holds one level); kept for older brushes
uniform float u_materialLodUv; // 0, likewise
uniform float u_tileSize;    // one tile of the maps on the surface
uniform float u_tileSamples; // the same, in image samples (uv projection)
uniform float u_heightScale; // displacement of height 1 - 0.5
#endif

// The image's cells W × H: u_cells, or N × N from u_size where a host sets only that.
ivec2 gridCells() { return u_cells.x > 0 ? u_cells : ivec2(u_size); }

struct BrushInput {
  ivec2 texel;
  vec2 uv;
  vec3 position;
  vec3 normal;
  float weight;   // falloff * strength * pressure * mask
  float distance; // to the centre, in radii
};

// The grid sample that integer position p stands for (core's wrap(SampleGrid, …)): in the
// octahedral tiling of the plane (core/src/octahedral.cpp's wrap()), for p within 4N of the image
// (further than any brush reaches), and in z whether the tiling reaches it by a half-turn (1) or a
// translation (0): a vector at p is the vector at the sample, negated when z is 1. A torus's
// period is W along i and H along j (within 4W and 4H); a plane clamps onto its boundary. Selects
// instead of `%`: a software rasterizer runs integer division lane by lane.
ivec3 wrapTexelTurn(ivec2 p) {
  int n = u_size;
  if (u_topology == 1) { // torus: period W, H; column W and row H are column and row 0 again
    ivec2 c = gridCells();
    int i = p.x < 0 ? p.x + 4 * c.x : p.x;
    int j = p.y < 0 ? p.y + 4 * c.y : p.y;
    i = i >= 2 * c.x ? i - 2 * c.x : i;
    j = j >= 2 * c.y ? j - 2 * c.y : j;
    i = i >= 2 * c.x ? i - 2 * c.x : i;
    j = j >= 2 * c.y ? j - 2 * c.y : j;
    i = i >= c.x ? i - c.x : i;
    j = j >= c.y ? j - c.y : j;
    return ivec3(i, j, 0);
  }
  if (u_topology == 2) return ivec3(clamp(p, ivec2(0), gridCells()), 0); // plane: its boundary
  int period = 2 * n;
  int i = p.x < 0 ? p.x + 2 * period : p.x;
  int j = p.y < 0 ? p.y + 2 * period : p.y;
  i = i >= period ? i - period : i;
  j = j >= period ? j - period : j;
  i = i >= period ? i - period : i;
  j = j >= period ? j - period : j;
  int turn = 0;
  if (i > n) { i = period - i; j = n - j; turn = 1; }
  if (j < 0) { i = n - i; j = -j; turn = 1 - turn; }
  else if (j > n) { i = n - i; j = period - j; turn = 1 - turn; }
  return ivec3(i, j, turn);
}

ivec2 wrapTexel(ivec2 p) { return wrapTexelTurn(p).xy; }

// The texel that t is identified with and that the brush computes as: a torus's column W and
// row H are its column and row 0, so a pass over both lines writes them equal (bit for bit: the
// same inputs, the same arithmetic) and needs no seaming pass after it.
ivec2 identifiedTexel(ivec2 t) {
  if (u_topology != 1) return t;
  ivec2 c = gridCells();
  return ivec2(t.x == c.x ? 0 : t.x, t.y == c.y ? 0 : t.y);
}

#if defined(BRUSH_REPARAMETERIZE)
// A reparameterize pass (manifest "pass": "reparameterize"): each sample's offset so far in this
// dab, in samples, in its own frame of the image. The sample now stands where the layers from
// before the dab are at texel + offset.
uniform sampler2D u_offsets;

// The grid triangle of the tiled plane that holds point q (cells split as core's cellSplit: along
// the anti-diagonal where the cell's quadrant indices have equal parity) as corners c0..c2 and
// q's barycentric weights: a value read through them lies on the piecewise-linear surface.
void cellTriangleAt(vec2 q, out ivec2 c0, out ivec2 c1, out ivec2 c2, out vec3 w) {
  ivec2 a = ivec2(floor(q));
  vec2 f = q - vec2(a);
  int shift = findMSB(max(u_size / 2, 1)); // floorDiv by N/2 (a power of two): arithmetic shift
  // The torus and plane split every cell along its anti-diagonal.
  bool antiDiagonal = u_topology != 0 || ((a.x >> shift) & 1) == ((a.y >> shift) & 1);
  if (antiDiagonal) {
    if (f.x + f.y <= 1.0) {
      c0 = a; c1 = a + ivec2(1, 0); c2 = a + ivec2(0, 1);
      w = vec3(1.0 - f.x - f.y, f.x, f.y);
    } else {
      c0 = a + ivec2(1, 1); c1 = a + ivec2(1, 0); c2 = a + ivec2(0, 1);
      w = vec3(f.x + f.y - 1.0, 1.0 - f.y, 1.0 - f.x);
    }
  } else if (f.x >= f.y) {
    c0 = a; c1 = a + ivec2(1, 0); c2 = a + ivec2(1, 1);
    w = vec3(1.0 - f.x, f.x - f.y, f.y);
  } else {
    c0 = a; c1 = a + ivec2(1, 1); c2 = a + ivec2(0, 1);
    w = vec3(1.0 - f.y, f.x, f.y - f.x);
  }
}

// Layer s at point q of the tiled plane, interpolated on the grid's own triangles.
vec4 planeValue(sampler2D s, vec2 q) {
  ivec2 c0, c1, c2;
  vec3 w;
  cellTriangleAt(q, c0, c1, c2, w);
  return w.x * texelFetch(s, wrapTexel(c0), 0) + w.y * texelFetch(s, wrapTexel(c1), 0) +
         w.z * texelFetch(s, wrapTexel(c2), 0);
}

// The offset of the sample at integer position c of the plane, in the plane's frame.
vec2 offsetAt(ivec2 c) {
  ivec3 t = wrapTexelTurn(c);
  vec2 o = texelFetch(u_offsets, t.xy, 0).xy;
  return t.z == 1 ? -o : o;
}

// The offset field at point q of the plane, interpolated on the grid's triangles.
vec2 planeOffset(vec2 q) {
  ivec2 c0, c1, c2;
  vec3 w;
  cellTriangleAt(q, c0, c1, c2, w);
  return w.x * offsetAt(c0) + w.y * offsetAt(c1) + w.z * offsetAt(c2);
}

// The sample's current position: the positions from before the dab at texel + its offset.
vec4 fetchPositions(ivec2 texel) {
  vec2 o = offsetAt(texel);
  return o == vec2(0.0) ? texelFetch(u_positions, wrapTexel(texel), 0)
                        : planeValue(u_positions, vec2(texel) + o);
}
vec4 fetchLayer(ivec2 texel) { return fetchPositions(texel); }
#else
vec4 fetchPositions(ivec2 texel) { return texelFetch(u_positions, wrapTexel(texel), 0); }
vec4 fetchLayer(ivec2 texel) { return texelFetch(u_layer, wrapTexel(texel), 0); }
#endif

#if defined(BRUSH_STROKE_START)
// The positions (xyz) and saliency (w) at texel t as they were when the stroke began, wrapped
// across the seams as fetchPositions.
vec4 strokeStartAt(ivec2 t) { return texelFetch(u_strokeStart, wrapTexel(t), 0); }

// The stroke-start surface's unit normal at texel t (central differences, as normalAt).
vec3 strokeStartNormalAt(ivec2 t) {
  vec3 du = strokeStartAt(t + ivec2(1, 0)).xyz - strokeStartAt(t - ivec2(1, 0)).xyz;
  vec3 dv = strokeStartAt(t + ivec2(0, 1)).xyz - strokeStartAt(t - ivec2(0, 1)).xyz;
  vec3 n = cross(du, dv);
  if (dot(n, n) < 1e-20) {
    du = strokeStartAt(t + ivec2(1, 0)).xyz - strokeStartAt(t).xyz;
    n = cross(du, dv);
  }
  return dot(n, n) < 1e-30 ? u_centreNormal : normalize(n);
}
#endif

// Central differences through wrap(): a half-turn of the tiling negates both differences, so the
// cross product is the same on both sides of a seam. At the fold points (side midpoints) the two
// horizontal neighbours coincide; one-sided differences take over there.
vec3 normalAt(ivec2 t) {
  vec3 p = fetchPositions(t).xyz;
  vec3 du = fetchPositions(t + ivec2(1, 0)).xyz - fetchPositions(t - ivec2(1, 0)).xyz;
  vec3 dv = fetchPositions(t + ivec2(0, 1)).xyz - fetchPositions(t - ivec2(0, 1)).xyz;
  vec3 n = cross(du, dv);
  if (dot(n, n) < 1e-20) {
    du = fetchPositions(t + ivec2(1, 0)).xyz - p;
    dv = fetchPositions(t + ivec2(0, 1)).xyz - fetchPositions(t - ivec2(0, 1)).xyz;
    n = cross(du, dv);
  }
  if (dot(n, n) < 1e-30) return u_centreNormal;
  return normalize(n);
}

// The painted mask at texel t. An unpainted mask is one value everywhere: the host then leaves
// BRUSH_MASK_TEXTURE undefined and no texel is read (a texture read is costly on a CPU rasterizer).
float maskAt(ivec2 t) {
#if defined(BRUSH_MASK_TEXTURE)
  return texelFetch(u_mask, t, 0).r;
#else
  return u_maskFill;
#endif
}

float falloffAt(float d) {
  if (d >= 1.0) return 0.0;
#if defined(BRUSH_FALLOFF_LINEAR)
  return 1.0 - d;
#elif defined(BRUSH_FALLOFF_CONSTANT)
  return 1.0;
#elif defined(BRUSH_FALLOFF_CURVE)
  float x = d * float(u_falloffCurveSize - 1);
  int k = min(int(x), u_falloffCurveSize - 2);
  return mix(u_falloffCurve[k], u_falloffCurve[k + 1], x - float(k));
#else
  float s = 1.0 - d * d; // smooth: (1 - d^2)^2, flat at the centre and at the rim
  return s * s;
#endif
}

// Distance in samples from t to the centre sample over the octahedral tiling: the least distance
// to the centre's images under the half-turns about the side midpoints and the (±N, ±N)
// translations, which is all a brush narrower than N/2 can reach across seams and corners.
float uvDistance(ivec2 t) {
  vec2 p = vec2(t), c = vec2(u_centreTexel);
  float n = float(u_size);
  float d = length(p - c);
  if (u_topology == 2) return d; // plane: no images
  if (u_topology == 1) { // torus: the centre's translates by (±W, 0), (0, ±H) and (±W, ±H)
    vec2 q = abs(p - c);
    q = min(q, abs(q - vec2(gridCells())));
    return length(q);
  }
  d = min(d, length(p - (vec2(0.0, n) - c)));
  d = min(d, length(p - (vec2(2.0 * n, n) - c)));
  d = min(d, length(p - (vec2(n, 0.0) - c)));
  d = min(d, length(p - (vec2(n, 2.0 * n) - c)));
  d = min(d, length(p - (c + vec2(n, n))));
  d = min(d, length(p - (c + vec2(-n, -n))));
  d = min(d, length(p - (c + vec2(n, -n))));
  d = min(d, length(p - (c + vec2(-n, n))));
  return d;
}

// Fills the brush input of texel t; weight is 0 outside the brush's area. The normal costs
// six reads, so it is computed only when the manifest needs it ("needs": ["normal"]) or the area
// mode uses it (BRUSH_NEEDS_NORMAL) and the texel is inside the radius; otherwise it is the
// centre normal.
BrushInput brushInputAt(ivec2 t, vec4 value) {
  BrushInput b;
  b.texel = t;
  b.uv = vec2(t) / vec2(gridCells()); // (0, 0) to (1, 1) over the image
#if defined(BRUSH_ANCHORED)
  b.position = texelFetch(u_strokeStart, t, 0).xyz; // an anchored dab measures the start surface
#elif OCTACLAY_LAYER == LAYER_POSITIONS || OCTACLAY_LAYER == LAYER_ALL
  b.position = value.xyz; // value is the positions texel
#else
  b.position = texelFetch(u_positions, t, 0).xyz;
#endif
  b.normal = u_centreNormal;
#if defined(BRUSH_AREA_UV)
  b.distance = uvDistance(t) * (u_radius > 0.0 ? 1.0 / u_radius : 0.0);
#else
  b.distance = length(b.position - u_centre) / u_radius;
#endif
  b.weight = 0.0;
  if (b.distance >= 1.0) return b;
#if defined(BRUSH_NEEDS_NORMAL)
  b.normal = normalAt(t);
#endif
  float w = falloffAt(b.distance) * u_strength * u_pressure;
#if OCTACLAY_LAYER != LAYER_MASK
  w *= maskAt(t); // the mask brush itself must be able to paint masked areas
#endif
#if defined(BRUSH_AREA_VOLUME_NORMAL)
  if (dot(b.normal, u_centreNormal) < u_normalCosine) w = 0.0;
#endif
  b.weight = w;
  return b;
}
