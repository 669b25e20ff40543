// Procedural ground grid: 1 m minor and 5 m major lines, anti-aliased with screen-space derivatives,
// minor lines fading where they would alias, the whole ground fading into the background with
// distance; lit and shadowed like any surface.
#include "lighting.glsl"

in vec3 vWorldPos;
uniform vec3 uGroundColor;  // sRGB
uniform vec3 uMinorColor;   // sRGB
uniform vec3 uMajorColor;   // sRGB
uniform vec3 uAxisXColor;   // sRGB, the line z = 0
uniform vec3 uAxisZColor;   // sRGB, the line x = 0
uniform float uFadeStart;   // m from the camera
uniform float uFadeEnd;     // m
out vec4 fragColor;

// Coverage in [0,1] of lines every `spacing` metres, `widthPx` pixels wide.
float lines(vec2 coord, float spacing, float widthPx) {
  vec2 c = coord / spacing;
  vec2 d = max(fwidth(c), vec2(1e-6));
  vec2 g = abs(fract(c - 0.5) - 0.5) / d;  // pixels to the nearest line, per axis
  float cover = clamp(0.5 * widthPx + 0.5 - min(g.x, g.y), 0.0, 1.0);
  float aliasFade = 1.0 - smoothstep(0.15, 0.45, max(d.x, d.y));  // cells smaller than ~3 px
  return cover * aliasFade;
}

float axisLine(float coord, float widthPx) {
  float d = max(fwidth(coord), 1e-6);
  return clamp(0.5 * widthPx + 0.5 - abs(coord) / d, 0.0, 1.0);
}

void main() {
  vec2 xz = vWorldPos.xz;
  float dist = length(vWorldPos - uCameraPos);
  // Lines fade out before the ground does, so the horizon stays calm.
  float lineFade = 1.0 - smoothstep(0.25 * uFadeStart, 0.8 * uFadeEnd, dist);
  vec3 base = uGroundColor;
  base = mix(base, uMinorColor, lines(xz, 1.0, 1.2) * lineFade);
  base = mix(base, uMajorColor, lines(xz, 5.0, 1.8) * lineFade);
  base = mix(base, uAxisXColor, axisLine(xz.y, 2.2) * lineFade);
  base = mix(base, uAxisZColor, axisLine(xz.x, 2.2) * lineFade);
  vec3 color = shade(base, vWorldPos, vec3(0.0, 1.0, 0.0), 0.0);
  float alpha = 1.0 - smoothstep(uFadeStart, uFadeEnd, dist);
  fragColor = vec4(toSrgb(color), alpha);
}
