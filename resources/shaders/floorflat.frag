#version 330 core
in vec3 vWorldPos;
uniform vec3 uEye;
out vec4 fragColor;
void main() {
  fragColor = vec4(0.60, 0.62, 0.64, 1.0);
}
