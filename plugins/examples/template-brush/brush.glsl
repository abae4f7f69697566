// Template raise brush: moves each affected sample along the normal at the brush centre.
// One dab at full weight moves it by u_height brush radii. The host provides BrushInput, the
// u_* uniforms and the helpers (see plugins/examples/README.md) and calls brush() once per
// texel of the layer being written.

vec4 brush(vec4 value, BrushInput b) {
#if OCTACLAY_LAYER == LAYER_POSITIONS
  // Displacing along the centre's normal (not each sample's own) keeps a dab from splaying
  // the surface apart on curved regions.
  return vec4(value.xyz + u_centreNormal * (b.weight * u_radius * u_height), value.w);
#else
  return value;
#endif
}
