// Feature G is the specular amount; R (height detail) and B (reflectivity) pass through untouched.
vec4 brush(vec4 value, BrushInput b) {
  float w = clamp(b.weight, 0.0, 1.0);
  float target = u_mode == 1 ? u_layerFill.g : u_value;
  value.g = w >= 1.0 ? target : mix(value.g, target, w);
  return value;
}
