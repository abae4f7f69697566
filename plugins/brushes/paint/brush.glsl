vec4 brush(vec4 value, BrushInput b) {
  float w = clamp(b.weight, 0.0, 1.0);
  if (u_mode == 1) // erase: back to the layer's base colour; full weight restores it exactly
    return w >= 1.0 ? u_layerFill : mix(value, u_layerFill, w);
  return mix(value, u_color, w);
}
