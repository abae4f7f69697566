// main() of every brush pass: texels outside the brush's area keep their value bit-exactly.
#if defined(BRUSH_REPARAMETERIZE)
// One step of a reparameterize brush (the body defines brushOffset()): the sample moves by the
// step, at most BRUSH_MAX_STEP samples (a step field that short folds no cell), and its offset
// becomes the step plus the offset field where the step lands, so that the engine's one resample
// per dab (resample.glsl) reads the layers from before the dab. A step that is not finite, and
// any step at the ball's four side midpoints (half-turn centres of the tiling, where the two
// sides' steps must cancel), counts as none; a plane's boundary samples step only along it.
out vec4 o_offset;

// The least altitude of the grid triangles around texel t as its samples now stand in the image
// (texel + offset), 0 where one is folded. A sample that moves less than half of it, while its
// neighbours do the same, folds none of them: a triangle degenerates only when its three
// corners come within half its least altitude of one line.
float foldFreeReach(ivec2 t) {
  float least = 1e30;
  for (int cy = -1; cy <= 0; ++cy)
    for (int cx = -1; cx <= 0; ++cx)
      for (int k = 0; k < 2; ++k) {
        ivec2 c0, c1, c2;
        vec3 w;
        // A point inside each of the cell's two triangles, whichever diagonal splits it.
        cellTriangleAt(vec2(t + ivec2(cx, cy)) + (k == 0 ? vec2(0.1, 0.2) : vec2(0.8, 0.7)), c0, c1,
                       c2, w);
        vec2 r1 = vec2(c1 - c0), r2 = vec2(c2 - c0);
        float orientation = sign(r1.x * r2.y - r1.y * r2.x);
        vec2 p0 = vec2(c0) + offsetAt(c0), p1 = vec2(c1) + offsetAt(c1), p2 = vec2(c2) + offsetAt(c2);
        vec2 e1 = p1 - p0, e2 = p2 - p0;
        float area2 = orientation * (e1.x * e2.y - e1.y * e2.x);
        float longest = max(length(e1), max(length(e2), length(p2 - p1)));
        least = min(least, area2 / max(longest, 1e-30));
      }
  return max(least, 0.0);
}

void main() {
  ivec2 t = ivec2(gl_FragCoord.xy);
  vec2 offset = texelFetch(u_offsets, t, 0).xy;
  BrushInput b = brushInputAt(t, fetchPositions(t));
  int n = u_size, h = u_size / 2;
  bool midpoint = u_topology == 0 && ((t.x == 0 || t.x == n) && t.y == h ||
                                      (t.y == 0 || t.y == n) && t.x == h);
  vec2 step = b.weight != 0.0 && !midpoint ? brushOffset(b) : vec2(0.0);
  if (u_topology == 2) { // a plane's boundary sample slides along its boundary, never off it
    ivec2 c = gridCells();
    if (t.x == 0 || t.x == c.x) step.x = 0.0;
    if (t.y == 0 || t.y == c.y) step.y = 0.0;
  }
  float len = length(step);
  if (!(len <= BRUSH_MAX_STEP)) step = len < 1e30 ? step * (BRUSH_MAX_STEP / len) : vec2(0.0);
  if (step != vec2(0.0)) {
    // Where the step lands in the image (the field so far, composed), no farther than keeps
    // every cell around the sample unfolded.
    vec2 moved = step + planeOffset(vec2(t) + step) - offset;
    float reach = 0.49 * foldFreeReach(t), d = length(moved);
    offset += d > reach ? moved * (reach / d) : moved;
  }
  o_offset = vec4(offset, 0.0, 0.0);
}
#elif OCTACLAY_LAYER == LAYER_ALL
// One pass for every layer (the body defines brushLayers()): brushInputAt runs once, and each
// layer's value is the one from before the dab, whatever the body writes to another.
layout(location = 0) out vec4 o_positions;
layout(location = 1) out vec4 o_diffuse;
layout(location = 2) out vec4 o_feature;

void main() {
  loadDab();
  ivec2 t = ivec2(gl_FragCoord.xy);
  vec4 positions = texelFetch(u_positions, t, 0);
  BrushInput b = brushInputAt(identifiedTexel(t), positions);
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
  loadDab();
  ivec2 t = ivec2(gl_FragCoord.xy);
  vec4 value = texelFetch(u_layer, t, 0);
  BrushInput b = brushInputAt(identifiedTexel(t), value);
#if defined(BRUSH_IN_PLACE)
  if (b.weight == 0.0) discard;
#endif
  o_value = b.weight != 0.0 ? brush(value, b) : value; // negative weights pull
}
#endif
