// Ground quad on y = 0 centred under the camera target; the grid itself is procedural (grid.frag).
layout(location = 0) in vec3 aPosition;  // unit plane, x,z in [-1,1]
uniform vec2 uCenter;   // world x,z, m
uniform float uExtent;  // half size, m
uniform mat4 uViewProj;
out vec3 vWorldPos;
void main() {
  vWorldPos = vec3(uCenter.x + aPosition.x * uExtent, 0.0, uCenter.y + aPosition.z * uExtent);
  gl_Position = uViewProj * vec4(vWorldPos, 1.0);
}
