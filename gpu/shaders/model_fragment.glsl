#version 430 core
// Per-pixel shading from the full-resolution normal map, so detail finer than the displayed
// triangles still shows; headlight diffuse plus a little specular.
uniform sampler2D u_normals;
uniform sampler2D u_diffuse;
uniform sampler2D u_mask;
uniform sampler2D u_feature;     // R height detail, G specular, B reflectivity
uniform sampler2D u_environment; // equirectangular, +y up
uniform bool u_hasEnvironment;
uniform bool u_featurePainted;   // else every texel is u_featureFill
uniform vec3 u_featureFill;
uniform bool u_maskPainted;
uniform float u_maskFill;
uniform int u_preview; // 0 shaded, 1 diffuse, 2 height detail, 3 specular, 4 reflectivity, 5 mask
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
  if (u_showMask && u_preview == 0) {
    float blocked = 1.0 - clamp(texture(u_mask, v_uv).r, 0.0, 1.0);
    albedo = mix(albedo, vec3(0.15, 0.25, 0.9), 0.6 * blocked);
  }
  vec3 feature = u_featurePainted ? texture(u_feature, v_uv).rgb : u_featureFill;
  float specularAmount = clamp(feature.g, 0.0, 1.0);
  float reflectivity = clamp(feature.b, 0.0, 1.0);
  float lambert = max(dot(n, toEye), 0.0);
  // Headlight: the highlight sits where the normal faces the eye; its strength is the specular
  // channel (0.25, the default, gives the clay's soft sheen).
  float specular = pow(lambert, 48.0) * specularAmount * 0.6;
  vec3 colour = albedo * (0.18 + 0.82 * lambert) + vec3(specular);
  if (reflectivity > 0.0 && u_hasEnvironment) {
    vec3 r = reflect(-toEye, n);
    vec2 e = vec2(atan(r.z, r.x) / 6.2831853 + 0.5, acos(clamp(r.y, -1.0, 1.0)) / 3.1415927);
    colour = mix(colour, texture(u_environment, e).rgb, reflectivity);
  }
  if (u_preview == 1) colour = albedo;
  else if (u_preview == 2) colour = vec3(clamp(0.5 + 4.0 * feature.r, 0.0, 1.0));
  else if (u_preview == 3) colour = vec3(specularAmount);
  else if (u_preview == 4) colour = vec3(reflectivity);
  else if (u_preview == 5)
    colour = vec3(clamp(u_maskPainted ? texture(u_mask, v_uv).r : u_maskFill, 0.0, 1.0));
  if (u_showBrush) {
    float d = length(v_position - u_brushCentre);
    // fwidth jumps at silhouettes (neighbouring pixels lie on far-apart surface): cap it.
    float width = clamp(fwidth(d) * 1.5, 1e-6, 0.08 * u_brushRadius);
    float ring = 1.0 - smoothstep(0.5 * width, width, abs(d - u_brushRadius));
    colour = mix(colour, u_brushColour, ring);
  }
  o_colour = vec4(colour, 1.0);
}
