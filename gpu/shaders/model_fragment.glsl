// Per-pixel shading from the full-resolution normal map, so detail finer than the displayed
// triangles still shows: headlight diffuse, a highlight scaled by the specular channel and the
// environment reflected by the reflectivity channel. The host compiles one variant per state
// (DIFFUSE_TEXTURE, FEATURE_TEXTURE, MASK_TINT, REFLECTION, PREVIEW n): a software rasterizer
// pays for every texture read a shader contains, taken or not, so unpainted layers are
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

in vec3 v_position;
in vec2 v_uv;
out vec4 o_colour;

// The heat maps' one colour scale: blue (0) through cyan, green and yellow to red (1).
vec3 heatColour(float s) {
  return clamp(vec3(4.0 * s - 2.0, s < 0.5 ? 4.0 * s : 4.0 - 4.0 * s, 2.0 - 4.0 * s), 0.0, 1.0);
}

void main() {
  vec3 n = texture(u_normals, v_uv).xyz * 2.0 - 1.0;
  n = dot(n, n) > 1e-12 ? normalize(n) : vec3(0.0, 0.0, 1.0);
  vec3 toEye = normalize(u_eye - v_position);
  if (dot(n, toEye) < 0.0 && !gl_FrontFacing) n = -n; // seen from inside
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
  albedo = mix(albedo, vec3(0.15, 0.25, 0.9), 0.6 * (1.0 - mask));
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
  o_colour = vec4(colour, 1.0);
}
