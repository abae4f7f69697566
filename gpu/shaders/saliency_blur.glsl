// Saliency, pass 3: one direction of a separable Gaussian over the octahedral tiling of the
// plane. The tiling's symmetries are translations and half-turns, which map rows to rows and
// columns to columns, so a horizontal then a vertical pass through wrap() is the 2D Gaussian
// over the tiled surface. The host prepends the version and the prelude (wrapTexel, u_size).
uniform sampler2D u_source;
uniform ivec2 u_direction;
uniform int u_taps; // the kernel has 2 u_taps + 1 weights, centre at index u_taps
// The normalised kernel as core::computeSaliency builds it (summed in the same order).
layout(std430, binding = 1) readonly buffer Kernel {
  float kernel[];
};
out vec4 o_value;

void main() {
  ivec2 s = ivec2(gl_FragCoord.xy);
  float sum = 0.0;
  int along = u_direction.x != 0 ? s.x : s.y;
  int last = u_direction.x != 0 ? gridCells().x : gridCells().y; // W or H
  if (along - u_taps >= 0 && along + u_taps <= last) {
    // Every tap inside the image: no wrap (most texels; a software rasterizer pays for each op).
    for (int d = -u_taps; d <= u_taps; ++d)
      sum += kernel[d + u_taps] * texelFetch(u_source, s + d * u_direction, 0).r;
  } else {
    for (int d = -u_taps; d <= u_taps; ++d)
      sum += kernel[d + u_taps] * texelFetch(u_source, wrapTexel(s + d * u_direction), 0).r;
  }
  o_value = vec4(sum, 0.0, 0.0, 0.0);
}
