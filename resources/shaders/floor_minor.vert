#version 330 core
// A large floor quad; the grid is drawn procedurally in the fragment shader.
in vec3 aPosition;
in vec3 aNormal;
uniform mat4 uModel;
uniform mat4 uViewProj;
out vec3 vWorldPos;
void main() {
  vec4 wp = uModel * vec4(aPosition, 1.0);
  vWorldPos = wp.xyz;
  gl_Position = uViewProj * wp;
}
