#version 430 core
// Per-pixel shading from the full-resolution normal map, so detail finer than the displayed
// triangles still shows; headlight diffuse plus a little specular.
uniform sampler2D u_normals;
uniform sampler2D u_diffuse;
uniform sampler2D u_mask;
uniform vec3 u_eye;
uniform bool u_showDiffuse;
uniform bool u_diffusePainted; // else every texel is u_diffuseFill
uniform vec3 u_diffuseFill;
uniform bool u_showMask;
uniform bool u_showBrush;
uniform vec3 u_brushCentre;
uniform float u_brushRadius;
uniform vec3 u_brushColour;

in vec3 v_position;
in vec2 v_uv;
out vec4 o_colour;

void main() {
  vec3 n = texture(u_normals, v_uv).xyz * 2.0 - 1.0;
  n = dot(n, n) > 1e-12 ? normalize(n) : vec3(0.0, 0.0, 1.0);
  vec3 toEye = normalize(u_eye - v_position);
  if (dot(n, toEye) < 0.0 && !gl_FrontFacing) n = -n; // seen from inside
  vec3 albedo = !u_showDiffuse     ? vec3(0.8, 0.78, 0.74)
                : u_diffusePainted ? texture(u_diffuse, v_uv).rgb
                                   : u_diffuseFill;
  if (u_showMask) {
    float blocked = 1.0 - clamp(texture(u_mask, v_uv).r, 0.0, 1.0);
    albedo = mix(albedo, vec3(0.15, 0.25, 0.9), 0.6 * blocked);
  }
  float lambert = max(dot(n, toEye), 0.0);
  float specular = pow(lambert, 48.0);
  vec3 colour = albedo * (0.18 + 0.82 * lambert) + vec3(0.12 * specular);
  if (u_showBrush) {
    float d = length(v_position - u_brushCentre);
    // fwidth jumps at silhouettes (neighbouring pixels lie on far-apart surface): cap it.
    float width = clamp(fwidth(d) * 1.5, 1e-6, 0.08 * u_brushRadius);
    float ring = 1.0 - smoothstep(0.5 * width, width, abs(d - u_brushRadius));
    colour = mix(colour, u_brushColour, ring);
  }
  o_colour = vec4(colour, 1.0);
}
