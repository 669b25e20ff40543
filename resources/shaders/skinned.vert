// Linear blend skinning: v' = sum_k w_k * Bones[id_k] * v, then the model matrix. Shares lit.frag.
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in ivec4 aBoneIds;
layout(location = 3) in vec4 aBoneWeights;

layout(std140) uniform Bones {
  mat4 uBones[128];
};
uniform mat4 uModel;
uniform mat4 uViewProj;
uniform vec4 uColor;

out vec3 vWorldPos;
out vec3 vNormal;
out vec4 vColor;

void main() {
  mat4 skin = aBoneWeights.x * uBones[aBoneIds.x] + aBoneWeights.y * uBones[aBoneIds.y] +
              aBoneWeights.z * uBones[aBoneIds.z] + aBoneWeights.w * uBones[aBoneIds.w];
  mat4 m = uModel * skin;
  vec4 world = m * vec4(aPosition, 1.0);
  vNormal = normalize(transpose(inverse(mat3(m))) * aNormal);
  vWorldPos = world.xyz;
  vColor = uColor;
  gl_Position = uViewProj * world;
}
