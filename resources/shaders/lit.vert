// Instanced lit primitives: per-vertex position/normal, per-instance model matrix and colour.
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in mat4 aModel;  // locations 2..5
layout(location = 6) in vec4 aColor;

uniform mat4 uViewProj;

out vec3 vWorldPos;
out vec3 vNormal;
out vec4 vColor;

void main() {
  vec4 world = aModel * vec4(aPosition, 1.0);
  // Normal matrix of a rotation * scale model: R S^-1 = M S^-2, with S^2 the squared column lengths.
  mat3 m = mat3(aModel);
  vec3 s2 = vec3(dot(m[0], m[0]), dot(m[1], m[1]), dot(m[2], m[2]));
  vNormal = normalize(m * (aNormal / max(s2, vec3(1e-12))));
  vWorldPos = world.xyz;
  vColor = aColor;
  gl_Position = uViewProj * world;
}
