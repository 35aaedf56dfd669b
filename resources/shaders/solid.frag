#version 330 core
// Hemisphere ambient plus a warm key light and a cool fill, Blinn-Phong highlights, gamma 2.2.
in vec3 vWorldPos;
in vec3 vNormal;
uniform vec4 uColor;
uniform vec3 uEye;
uniform vec3 uKeyDir;
uniform vec3 uFillDir;
out vec4 fragColor;
void main() {
  vec3 n = normalize(vNormal);
  vec3 v = normalize(uEye - vWorldPos);
  if (dot(n, v) < 0.0) n = -n;
  vec3 base = pow(uColor.rgb, vec3(2.2));
  float hemi = 0.5 + 0.5 * n.z;
  vec3 ambient = mix(vec3(0.10, 0.09, 0.08), vec3(0.30, 0.32, 0.36), hemi);
  vec3 key = normalize(uKeyDir);
  vec3 fill = normalize(uFillDir);
  float dk = max(dot(n, key), 0.0);
  float df = max(dot(n, fill), 0.0);
  vec3 h = normalize(key + v);
  float spec = pow(max(dot(n, h), 0.0), 48.0) * 0.35;
  vec3 c = base * (ambient + vec3(1.0, 0.96, 0.9) * dk * 0.95 + vec3(0.55, 0.62, 0.75) * df * 0.35)
      + vec3(spec);
  fragColor = vec4(pow(c, vec3(1.0 / 2.2)), uColor.a);
}
