// Thick lines: one instance per segment, drawn as a 4-vertex triangle strip (gl_VertexID picks the
// corner). The quad lies in screen space, uWidth pixels wide (core profile and WebGL2 have no
// glLineWidth > 1). The segment is clipped against the near plane first so that an end point behind
// the eye does not flip; ends are extended by half the width so polylines join without gaps.
layout(location = 0) in vec3 aStart;
layout(location = 1) in vec4 aStartColor;
layout(location = 2) in vec3 aEnd;
layout(location = 3) in vec4 aEndColor;
uniform mat4 uViewProj;
uniform vec2 uViewport;  // pixels
uniform float uWidth;    // pixels
out vec4 vColor;
// Pixels from the centre line, interpolated linearly in screen space: the fragment shader divides
// vAcrossW by vW (perspective-correct interpolation of x*w over that of w gives the screen-linear x).
out float vAcrossW;
out float vW;

void main() {
  vec4 p0 = uViewProj * vec4(aStart, 1.0), p1 = uViewProj * vec4(aEnd, 1.0);
  vec4 c0 = aStartColor, c1 = aEndColor;
  float d0 = p0.z + p0.w, d1 = p1.z + p1.w;  // signed distance to the near plane
  if (d0 < 0.0 && d1 < 0.0) {                // wholly behind: a degenerate quad outside the clip box
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
    vColor = c0; vAcrossW = 0.0; vW = 1.0;
    return;
  }
  if (d0 < 0.0) {
    float t = d0 / (d0 - d1);
    p0 = mix(p0, p1, t);
    c0 = mix(c0, c1, t);
  } else if (d1 < 0.0) {
    float t = d1 / (d1 - d0);
    p1 = mix(p1, p0, t);
    c1 = mix(c1, c0, t);
  }
  vec2 s0 = p0.xy / p0.w * 0.5 * uViewport;
  vec2 s1 = p1.xy / p1.w * 0.5 * uViewport;
  vec2 dir = s1 - s0;
  float len = length(dir);
  dir = len > 1e-4 ? dir / len : vec2(1.0, 0.0);
  vec2 normal = vec2(-dir.y, dir.x);
  float half_ = 0.5 * uWidth + 1.0;  // +1 px for the anti-aliased fringe
  vec2 toNdc = 2.0 / uViewport;
  vec2 along = dir * (0.5 * uWidth) * toNdc;
  vec2 across = normal * half_ * toNdc;
  // Strip order: start +, start -, end +, end -.
  bool atEnd = gl_VertexID >= 2;
  float side = (gl_VertexID == 0 || gl_VertexID == 2) ? 1.0 : -1.0;
  vec4 p = atEnd ? p1 : p0;
  vec2 offset = side * across + (atEnd ? along : -along);
  gl_Position = vec4(p.xy + offset * p.w, p.zw);
  vColor = atEnd ? c1 : c0;
  vAcrossW = side * half_ * p.w;
  vW = p.w;
}
