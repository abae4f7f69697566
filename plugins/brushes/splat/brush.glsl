// Material splat: one dab writes relief (positions), colour (diffuse) and the feature channels
// (R height detail, G specular, B reflectivity), each blended toward the material by the dab's
// weight, so overlapping dabs converge to the material instead of piling it up. All three in one
// pass (brushLayers): the material is sampled once per texel, at its position before the dab.
// Diffuse is mixed by the GPU's blender ("mix" in the manifest): the pass never reads it.

// Where sample b meets the material's maps, in tiles.
vec2 splatCoordinates(BrushInput b) {
  if (u_projection == 1) // uv: the naive variant, through the image's own coordinates
    return vec2(b.texel - u_centreTexel) / u_tileSamples;
  vec3 d = b.position - u_centre;
  return vec2(dot(d, u_projectionRight), dot(d, u_projectionUp)) / u_tileSize;
}

void brushLayers(inout vec4 positions, inout vec4 diffuse, inout vec4 feature, BrushInput b) {
  vec2 c = splatCoordinates(b);
  float w = clamp(b.weight, 0.0, 1.0);
  // The host bound the level this dab needs; textureLod: implicit derivatives are undefined in
  // a brush pass.
  vec4 surface, colour;
  if (u_projection == 1) {
    surface = textureLod(u_materialSurfaceUv, c, 0.0);
    colour = textureLod(u_materialColourUv, c, 0.0);
  } else {
    surface = textureLod(u_materialSurface, c, 0.0);
    colour = textureLod(u_materialColour, c, 0.0);
  }
  float height = (surface.r - 0.5) * u_relief; // signed height detail
  // Displace by the change of height detail this dab makes (feature still holds the old detail),
  // along the projection, like the paint: relief and colour line up seen from the view.
  float before = feature.r;
  float after = mix(before, height, w);
  positions.xyz -= u_projectionDir * ((after - before) * u_heightScale);
  diffuse = vec4(colour.rgb, w * colour.a); // mixed in by the blender (manifest "mix")
  feature.rgb = vec3(after, mix(feature.g, surface.g, w), mix(feature.b, surface.b, w));
}
