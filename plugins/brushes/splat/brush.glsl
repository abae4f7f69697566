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
  float height = (texture(u_materialHeight, c).r - 0.5) * u_relief; // signed height detail
#if OCTACLAY_LAYER == LAYER_POSITIONS
  // Displace by the change of height detail this dab makes (the feature layer still holds the
  // old detail: the host runs this pass before the feature pass).
  float before = texelFetch(u_featureLayer, b.texel, 0).r;
  float after = mix(before, height, w);
  return vec4(value.xyz + b.normal * ((after - before) * u_heightScale), value.w);
#elif OCTACLAY_LAYER == LAYER_DIFFUSE
  vec4 colour = texture(u_materialColour, c);
  return vec4(mix(value.rgb, colour.rgb, w * colour.a), value.a);
#else
  return vec4(mix(value.r, height, w), mix(value.g, texture(u_materialSpecular, c).r, w),
              mix(value.b, texture(u_materialReflectivity, c).r, w), value.a);
#endif
}
