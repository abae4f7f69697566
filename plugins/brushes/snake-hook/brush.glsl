// A drag stroke: each dab is centred where the previous one left the tip and moves every sample
// by the drag's movement since that dab times its weight, so the tip follows the path. A
// movement of at most the spacing (0.1 radius) per dab keeps the displacement field from folding.
vec4 brush(vec4 value, BrushInput b) {
  return vec4(value.xyz + u_strokeDelta * b.weight, value.w);
}
