// main() of every brush pass: texels outside the brush's area keep their value bit-exactly.
#if OCTACLAY_LAYER == LAYER_ALL
// One pass for every layer (the body defines brushLayers()): brushInputAt runs once, and each
// layer's value is the one from before the dab, whatever the body writes to another.
layout(location = 0) out vec4 o_positions;
layout(location = 1) out vec4 o_diffuse;
layout(location = 2) out vec4 o_feature;

void main() {
  ivec2 t = ivec2(gl_FragCoord.xy);
  vec4 positions = texelFetch(u_positions, t, 0);
  BrushInput b = brushInputAt(t, positions);
#if defined(BRUSH_IN_PLACE)
  if (b.weight == 0.0) discard; // the targets are the layers: nothing to write, nothing to sample
#endif
  // A mixed layer is not read: the body gives (colour, amount) and the blender mixes it in.
#if defined(BRUSH_MIX_DIFFUSE)
  vec4 diffuse = vec4(0.0);
#else
  vec4 diffuse = texelFetch(u_diffuseLayer, t, 0);
#endif
#if defined(BRUSH_MIX_FEATURE)
  vec4 feature = vec4(0.0);
#else
  vec4 feature = texelFetch(u_featureLayer, t, 0);
#endif
  if (b.weight != 0.0) brushLayers(positions, diffuse, feature, b); // negative weights pull
  o_positions = positions;
  o_diffuse = diffuse;
  o_feature = feature;
}
#else
out vec4 o_value;

void main() {
  ivec2 t = ivec2(gl_FragCoord.xy);
  vec4 value = texelFetch(u_layer, t, 0);
  BrushInput b = brushInputAt(t, value);
#if defined(BRUSH_IN_PLACE)
  if (b.weight == 0.0) discard;
#endif
  o_value = b.weight != 0.0 ? brush(value, b) : value; // negative weights pull
}
#endif
