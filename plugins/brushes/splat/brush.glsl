// Material splat: one dab writes relief (positions), colour (diffuse) and the feature channels
// (R height detail, G specular, B reflectivity), each blended toward the material by the dab's
// weight, so overlapping dabs converge to the material instead of piling it up.

// Where sample b meets the material's maps, in tiles.
vec2 splatCoordinates(BrushInput b) {
  if (u_projection == 1) // uv: the naive variant, through the image's own coordinates
    return vec2(b.texel - u_centreTexel) / u_tileSamples;
  vec3 d = b.position - u_centre;
  return vec2(dot(d, u_projectionRight), dot(d, u_projectionUp)) / u_tileSize;
}

vec4 brush(vec4 value, BrushInput b) {
  vec2 c = splatCoordinates(b);
  float w = clamp(b.weight, 0.0, 1.0);
  // textureLod with the host's level: implicit derivatives are undefined in a brush pass.
  vec4 surface = textureLod(u_materialSurface, c, u_materialLod);
  float height = (surface.r - 0.5) * u_relief; // signed height detail
#if OCTACLAY_LAYER == LAYER_POSITIONS
  // Displace by the change of height detail this dab makes (the feature layer still holds the
  // old detail: the host runs this pass before the feature pass).
  float before = texelFetch(u_featureLayer, b.texel, 0).r;
  float after = mix(before, height, w);
  // Along the projection, like the paint: relief and colour line up seen from the view.
  return vec4(value.xyz - u_projectionDir * ((after - before) * u_heightScale), value.w);
#elif OCTACLAY_LAYER == LAYER_DIFFUSE
  vec4 colour = textureLod(u_materialColour, c, u_materialLod);
  return vec4(mix(value.rgb, colour.rgb, w * colour.a), value.a);
#else
  return vec4(mix(value.r, height, w), mix(value.g, surface.g, w), mix(value.b, surface.b, w),
              value.a);
#endif
}
