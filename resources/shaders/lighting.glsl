// Shared lighting for lit surfaces and the ground: Blinn-Phong with one directional light, a
// hemisphere ambient term, and a PCF-filtered shadow map. Colours are authored in sRGB and lit in
// linear space.
uniform vec3 uLightDir;        // unit, from the surface towards the light (world)
uniform vec3 uLightColor;      // linear
uniform vec3 uSkyAmbient;      // linear, ambient from above
uniform vec3 uGroundAmbient;   // linear, ambient from below
uniform vec3 uCameraPos;       // world, m
uniform mat4 uLightViewProj;   // world -> light clip space
uniform sampler2DShadow uShadowMap;
uniform float uShadowTexel;    // 1 / shadow map size
uniform float uShadowNormalOffset;  // world m, pushes the lookup off the surface (acne)
uniform int uShadowsOn;

vec3 toLinear(vec3 c) { return pow(max(c, vec3(0.0)), vec3(2.2)); }
vec3 toSrgb(vec3 c) { return pow(max(c, vec3(0.0)), vec3(1.0 / 2.2)); }

uniform int uShadowTaps;       // Poisson taps used, 1 to 12 (4 on software rendering)

// The first four taps lie one in each quadrant, so a 4-tap lookup is still centred.
const vec2 kPoisson[12] = vec2[](
    vec2(-0.696, 0.457), vec2(0.519, 0.767), vec2(0.473, -0.480), vec2(-0.792, -0.598),
    vec2(-0.326, -0.406), vec2(-0.840, -0.074), vec2(-0.203, 0.621), vec2(0.962, -0.195),
    vec2(0.185, -0.893), vec2(0.507, 0.064), vec2(0.896, 0.412), vec2(-0.322, -0.933));

// 1 = fully lit, 0 = fully shadowed. Normal-offset + small constant bias; up to 12 Poisson taps, each
// a hardware 2x2 comparison, over a 2.5-texel disc: soft edges without banding.
float shadowFactor(vec3 worldPos, vec3 n) {
  if (uShadowsOn == 0) return 1.0;
  float cosTheta = clamp(dot(n, uLightDir), 0.0, 1.0);
  vec3 p = worldPos + n * uShadowNormalOffset * (1.5 - cosTheta);
  vec4 lp = uLightViewProj * vec4(p, 1.0);
  vec3 s = lp.xyz / lp.w * 0.5 + 0.5;
  if (s.z >= 1.0 || s.x <= 0.0 || s.x >= 1.0 || s.y <= 0.0 || s.y >= 1.0) return 1.0;
  float bias = 0.0007;
  float lit = 0.0;
  int taps = clamp(uShadowTaps, 1, 12);
  for (int i = 0; i < 12; ++i) {
    if (i >= taps) break;
    lit += texture(uShadowMap, vec3(s.xy + kPoisson[i] * uShadowTexel * 2.5, s.z - bias));
  }
  return lit / float(taps);
}

// Lit colour (linear) of a surface with sRGB base colour.
vec3 shade(vec3 baseSrgb, vec3 worldPos, vec3 n, float specular) {
  vec3 base = toLinear(baseSrgb);
  vec3 v = normalize(uCameraPos - worldPos);
  if (dot(n, v) < 0.0) n = -n;  // two-sided: open tubes, planes, imported meshes
  float ndl = max(dot(n, uLightDir), 0.0);
  float shadow = shadowFactor(worldPos, n);
  vec3 h = normalize(uLightDir + v);
  float spec = specular * pow(max(dot(n, h), 0.0), 56.0) * ndl;
  vec3 ambient = mix(uGroundAmbient, uSkyAmbient, 0.5 + 0.5 * n.y);
  return base * (ambient + uLightColor * ndl * shadow) + uLightColor * spec * shadow;
}
