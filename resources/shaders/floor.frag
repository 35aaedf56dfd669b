#version 330 core
// Anti-aliased grid lines every 100 mm, stronger every 1000 mm, fading with distance.
// Alpha 0 marks floor pixels, which the edge smoothing pass (fxaa.frag) leaves alone.
in vec3 vWorldPos;
uniform vec3 uEye;
out vec4 fragColor;
float gridLine(vec2 p, float spacing, float width) {
  vec2 g = abs(fract(p / spacing - 0.5) - 0.5) * spacing;
  vec2 w = fwidth(p) * width;
  vec2 l = 1.0 - smoothstep(vec2(0.0), w, g);
  return max(l.x, l.y);
}
void main() {
  vec2 p = vWorldPos.xy;
  float minor = gridLine(p, 100.0, 1.0);
  float major = gridLine(p, 1000.0, 1.6);
  vec3 floorColor = vec3(0.60, 0.62, 0.64);
  vec3 c = mix(floorColor, vec3(0.45, 0.47, 0.50), minor * 0.7);
  c = mix(c, vec3(0.30, 0.32, 0.35), major);
  float d = length(vWorldPos.xy - uEye.xy);
  float fade = smoothstep(3000.0, 9000.0, d);
  c = mix(c, vec3(0.78, 0.80, 0.83), fade);
  fragColor = vec4(c, 0.0);  // alpha 0: not a solid, for fxaa.frag
}
