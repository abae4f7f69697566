// Per-pixel shading from the full-resolution normal map, so detail finer than the displayed
// triangles still shows: headlight diffuse, a highlight scaled by the specular channel and the
// environment reflected by the reflectivity channel, or a matcap (MATCAP), with the triangles'
// edges over it (WIREFRAME). The host compiles one variant per state (DIFFUSE_TEXTURE,
// FEATURE_TEXTURE, MASK_TINT, REFLECTION, MATCAP, WIREFRAME, LOD_VERTICES, PREVIEW n): a software
// rasterizer pays for every texture read a shader contains, taken or not, so unpainted layers are
// uniforms and unused reads are compiled out.
uniform sampler2D u_positions;   // w: saliency in [0, 1] (PREVIEW 6)
uniform sampler2D u_stretch;     // R: stretch_map.glsl's figure (PREVIEW 7)
uniform float u_meanSpacing;     // the surface's mean sample spacing (PREVIEW 7)
uniform sampler2D u_normals;
uniform sampler2D u_diffuse;
uniform sampler2D u_mask;
uniform sampler2D u_feature;     // R height detail, G specular, B reflectivity
uniform sampler2D u_environment; // equirectangular, +y up
uniform vec3 u_diffuseFill;      // every texel while the layer is unpainted (or hidden)
uniform vec3 u_featureFill;
uniform float u_maskFill;
uniform vec3 u_eye;
uniform bool u_showBrush;
uniform vec3 u_brushCentre;
uniform float u_brushRadius;
uniform vec3 u_brushColour;
uniform sampler2D u_matcap;      // a lit sphere seen head-on, x right, y up (MATCAP)
uniform vec3 u_viewRight, u_viewUp;
uniform int u_side;              // M + 1: the displayed level's vertices a side (WIREFRAME)
uniform int u_imageSide;         // N + 1
uniform int u_step;              // the displayed level's sample step

in vec3 v_position;
in vec2 v_uv;
#if defined(WIREFRAME) && defined(LOD_VERTICES)
in vec3 v_corner;
#elif defined(WIREFRAME)
in vec2 v_cell;
#endif
out vec4 o_colour;

// The masked areas' tint: orange, hatched in screen space, so it never reads as paint.
const vec3 kMaskTint = vec3(1.0, 0.45, 0.0);

// The heat maps' one colour scale: blue (0) through cyan, green and yellow to red (1).
vec3 heatColour(float s) {
  return clamp(vec3(4.0 * s - 2.0, s < 0.5 ? 4.0 * s : 4.0 - 4.0 * s, 2.0 - 4.0 * s), 0.0, 1.0);
}

#if defined(WIREFRAME)
// The narrowest cell on screen whose lines are drawn, in pixels: the default display detail put
// a line every 2 or 3 pixels and darkened the whole model; finer cells show a coarser level's.
const float kMinCellPixels = 24.0;

float edgeCover(float pixels) {
  return 1.0 - smoothstep(0.5, 1.25, pixels);
}

#if !defined(LOD_VERTICES)
// How much of an edge of the level with cells of `level` displayed cells (1, 2, 4 …: a coarser
// level's triangles are unions of the displayed ones) covers this pixel.
// widths: fwidth of g.x, g.y, g.x + g.y and g.x - g.y (taken once, in uniform control flow).
float gridWireAt(vec2 g, vec4 widths, float level) {
  g /= level;
  float m = float(u_side - 1) / level;
  vec2 cell = min(floor(g), vec2(m - 1.0));
  // Lines i = const, j = const, and the diagonal: i + j = const where the cell's split is
  // anti-diagonal, i - j = const where it is not.
  bool anti = (cell.x < 0.5 * m) == (cell.y < 0.5 * m);
  vec3 along = vec3(g, anti ? g.x + g.y : g.x - g.y);
  vec3 width = vec3(widths.xy, anti ? widths.z : widths.w) / level;
  vec3 d = abs(along - round(along)) / max(width, vec3(1e-6));
  return edgeCover(min(d.x, min(d.y, d.z)));
}
#endif

// How much of an edge covers this pixel: 1 on a triangle edge of the displayed level (the
// grid's lines and each cell's diagonal, split as model_chunks.cpp splits it) or of the LOD,
// fading over about a pixel. Where the displayed cells are narrower than kMinCellPixels on
// screen, the edges of the coarser level whose cells are not (every 2nd, 4th … line), the next
// finer level's fading in as its cells widen, so the surface stays visible between the lines.
float wireAt() {
#if defined(LOD_VERTICES)
  vec3 d = v_corner / max(fwidth(v_corner), vec3(1e-6));
  return edgeCover(min(d.x, min(d.y, d.z)));
#else
  vec2 g = v_cell;
  vec4 widths = fwidth(vec4(g, g.x + g.y, g.x - g.y));
  float cellPixels = 1.0 / max(max(widths.x, widths.y), 1e-6);
  float coarsest = max(float(u_side - 1) * 0.5, 1.0);
  float x = clamp(log2(kMinCellPixels / cellPixels), 0.0, log2(coarsest));
  float level = exp2(floor(x));
  float coarse = gridWireAt(g, widths, min(2.0 * level, coarsest));
  return max(coarse, gridWireAt(g, widths, level) * (1.0 - fract(x)));
#endif
}
#endif

void main() {
  vec3 toEye = normalize(u_eye - v_position);
  // The triangle's own normal, on the side the eye sees: the fallback where the map's fails.
  vec3 face = cross(dFdx(v_position), dFdy(v_position));
  face = dot(face, face) > 1e-30 ? normalize(face) : toEye;
  if (dot(face, toEye) < 0.0) face = -face;
  vec3 n = texture(u_normals, v_uv).xyz * 2.0 - 1.0;
  float mapLength = length(n);
  n = mapLength > 1e-6 ? n / mapLength : face;
  if (dot(n, toEye) < 0.0 && !gl_FrontFacing) n = -n; // seen from inside
  // Where the image stretches the map's normal fails three ways, and the triangle's normal
  // takes over smoothly: the filter blends full-resolution normals that disagree (a short
  // vector); a normal faces away from both the triangle it shades and the eye; one pixel spans
  // many texels, so the unfiltered map aliases into speckles (where the displayed triangles are
  // about a pixel too, their normal loses nothing).
  float footprint = max(length(dFdx(v_uv)), length(dFdy(v_uv))) * float(u_imageSide);
#if defined(LOD_VERTICES)
  float aliasing = 0.0; // the LOD's triangles may be large anywhere: keep the map
#else
  float aliasing =
      smoothstep(2.0, 6.0, footprint) * (1.0 - smoothstep(1.5, 3.0, float(u_step) / footprint));
#endif
  // A map normal far from a coarse level's triangle is detail unless it also turns from the eye.
  float agrees = max(smoothstep(-0.2, 0.25, dot(n, face)), smoothstep(-0.05, 0.1, dot(n, toEye)));
  float trust = smoothstep(0.35, 0.7, mapLength) * agrees * (1.0 - aliasing);
  vec3 mapNormal = n;
  n = normalize(mix(face, n, trust));
  // A visible surface faces the eye, so where one estimate turns from it though the other faces
  // it (the map's normal of a fold a coarse triangle cuts across, a crumpled cell's triangle seen
  // edge-on) the darker is wrong: it shaded as black speckles and stripes. The normal is tilted
  // towards the eye, keeping its bearing, until it faces it half as much as the better estimate.
  float best = max(dot(face, toEye), dot(mapNormal, toEye));
  // Where both turn from the eye at one pixel (noise where a pixel spans many texels), the
  // pixel's 2×2 quad, over which derivatives are taken, says how the surface around it faces.
  // +1 on the quad's first pixel, whichever way the target's rows run (a window's may run
  // top down, so its quads need not start on even rows).
  vec2 parity = mod(floor(gl_FragCoord.xy), 2.0);
  vec2 side = (1.0 - 2.0 * parity) * vec2(dFdx(parity.x), dFdy(parity.y));
  float quadBest = best + 0.5 * (side.x * dFdx(best) + side.y * dFdy(best));
  float floorCosine = 0.5 * max(best, quadBest);
  float facing = dot(n, toEye);
  vec3 across = n - facing * toEye;
  if (facing < floorCosine && dot(across, across) > 1e-12)
    n = normalize(across) * sqrt(1.0 - floorCosine * floorCosine) + floorCosine * toEye;
#if defined(DIFFUSE_TEXTURE)
  vec3 albedo = texture(u_diffuse, v_uv).rgb;
#else
  vec3 albedo = u_diffuseFill;
#endif
#if defined(FEATURE_TEXTURE)
  vec3 feature = texture(u_feature, v_uv).rgb;
#else
  vec3 feature = u_featureFill;
#endif
#if defined(MASK_TINT) || PREVIEW == 5
  float mask = clamp(texture(u_mask, v_uv).r, 0.0, 1.0);
#else
  float mask = u_maskFill;
#endif
#if defined(MASK_TINT)
  float hatch = step(4.0, mod(gl_FragCoord.x + gl_FragCoord.y, 8.0));
  float maskTint = (0.45 + 0.35 * hatch) * (1.0 - mask);
#if !defined(MATCAP)
  albedo = mix(albedo, kMaskTint, maskTint);
#endif
#endif
  float specularAmount = clamp(feature.g, 0.0, 1.0);
  float reflectivity = clamp(feature.b, 0.0, 1.0);
  float lambert = max(dot(n, toEye), 0.0);
  // The highlight sits where the normal faces the eye; the default specular 0.25 gives the
  // clay's soft sheen.
  vec3 colour = albedo * (0.18 + 0.82 * lambert) + vec3(pow(lambert, 48.0) * specularAmount * 0.6);
#if defined(REFLECTION)
  vec3 r = reflect(-toEye, n);
  vec2 e = vec2(atan(r.z, r.x) / 6.2831853 + 0.5, acos(clamp(r.y, -1.0, 1.0)) / 3.1415927);
  colour = mix(colour, texture(u_environment, e).rgb, reflectivity);
#endif
#if defined(MATCAP)
  // View-space normal → the matcap's disc; the painted colour multiplies it where the paint
  // differs from the layer's fill (clay shows the matcap's own colour).
  vec2 onDisc = vec2(dot(n, u_viewRight), dot(n, u_viewUp));
  onDisc *= min(1.0, 0.995 / max(length(onDisc), 1e-6));
  colour = texture(u_matcap, onDisc * 0.5 + 0.5).rgb;
  float painted = smoothstep(0.02, 0.15, distance(albedo, u_diffuseFill));
  colour *= mix(vec3(1.0), 1.3 * albedo, painted);
#if defined(MASK_TINT)
  colour = mix(colour, kMaskTint, maskTint);
#endif
#endif
#if PREVIEW == 1
  colour = albedo;
#elif PREVIEW == 2
  colour = vec3(clamp(0.5 + 4.0 * feature.r, 0.0, 1.0));
#elif PREVIEW == 3
  colour = vec3(specularAmount);
#elif PREVIEW == 4
  colour = vec3(reflectivity);
#elif PREVIEW == 5
  colour = vec3(mask);
#elif PREVIEW == 6
  // Heat map: blue (0) through cyan, green and yellow to red (1), shaded lightly so the form
  // still reads.
  float s = clamp(texture(u_positions, v_uv).a, 0.0, 1.0);
  colour = heatColour(s) * (0.55 + 0.45 * lambert);
#elif PREVIEW == 7
  // Stretch over the mean spacing on a log scale, the saliency's colours: 2× or less blue (a
  // fresh sphere spans 0.6×–1.7×: the octahedral map is not conformal), 2.8× green, 4× or
  // more red (the layers panel's tooltip says so). The map is sampled at the nearest sample:
  // the figure belongs to a sample, not to the surface between.
  float stretch = texture(u_stretch, v_uv).r / max(u_meanSpacing, 1e-30);
  float s = clamp(log2(max(stretch, 1e-6)) - 1.0, 0.0, 1.0);
  colour = heatColour(s) * (0.55 + 0.45 * lambert);
#endif
  if (u_showBrush) {
    float d = length(v_position - u_brushCentre);
    // fwidth jumps at silhouettes (neighbouring pixels lie on far-apart surface): cap it.
    float width = clamp(fwidth(d) * 1.5, 1e-6, 0.08 * u_brushRadius);
    float ring = 1.0 - smoothstep(0.5 * width, width, abs(d - u_brushRadius));
    colour = mix(colour, u_brushColour, ring);
  }
#if defined(WIREFRAME)
  colour = mix(colour, vec3(0.08, 0.09, 0.12), 0.75 * wireAt());
#endif
  o_colour = vec4(colour, 1.0);
}
