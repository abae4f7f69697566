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

// The mip level for one image sample's footprint on the maps. Explicit, because a brush pass
// runs in non-uniform control flow where implicit derivatives are undefined.
float splatLod(BrushInput b) {
  float mapTexels = float(textureSize(u_materialColour, 0).x);
  float tiles; // of the maps one sample spans
  if (u_projection == 1)
    tiles = 1.0 / u_tileSamples;
  else
    tiles = length(fetchPositions(b.texel + ivec2(1, 0)).xyz - b.position) / u_tileSize;
  return max(0.0, log2(max(tiles * mapTexels, 1e-6)));
}

vec4 brush(vec4 value, BrushInput b) {
  vec2 c = splatCoordinates(b);
  float lod = splatLod(b);
  float w = clamp(b.weight, 0.0, 1.0);
  float height = (textureLod(u_materialHeight, c, lod).r - 0.5) * u_relief; // signed height detail
#if OCTACLAY_LAYER == LAYER_POSITIONS
  // Displace by the change of height detail this dab makes (the feature layer still holds the
  // old detail: the host runs this pass before the feature pass).
  float before = texelFetch(u_featureLayer, b.texel, 0).r;
  float after = mix(before, height, w);
  return vec4(value.xyz + b.normal * ((after - before) * u_heightScale), value.w);
#elif OCTACLAY_LAYER == LAYER_DIFFUSE
  vec4 colour = textureLod(u_materialColour, c, lod);
  return vec4(mix(value.rgb, colour.rgb, w * colour.a), value.a);
#else
  return vec4(mix(value.r, height, w), mix(value.g, textureLod(u_materialSpecular, c, lod).r, w),
              mix(value.b, textureLod(u_materialReflectivity, c, lod).r, w), value.a);
#endif
}
