#version 330 core
// Edge smoothing of a frame drawn with one sample per pixel. Where the luma contrast across
// the pixel's four neighbours is high, the pixel is blended toward the neighbour across the
// edge, more where it differs more from its neighbourhood's average. This is the sub-pixel
// step of T. Lottes' FXAA (NVIDIA white paper, 2009) without the search along the edge; the
// code is written for this renderer. Only unfiltered reads (texelFetch), five per pixel:
// Mesa's llvmpipe pays several times more for each filtered read.
uniform sampler2D uScene;
// Pixels outside [x0, x1) x [y0, y1) are copied as they are (a pass that also copies).
uniform ivec4 uSmooth;
out vec4 fragColor;

float luma(vec3 c) {
  return dot(c, vec3(0.299, 0.587, 0.114));
}

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  ivec2 last = textureSize(uScene, 0) - 1;
  vec4 m = texelFetch(uScene, p, 0);
  if (any(lessThan(p, uSmooth.xy)) || any(greaterThanEqual(p, uSmooth.zw))) {
    fragColor = m;
    return;
  }
  vec4 n = texelFetch(uScene, min(p + ivec2(0, 1), last), 0);
  vec4 s = texelFetch(uScene, max(p - ivec2(0, 1), ivec2(0)), 0);
  vec4 e = texelFetch(uScene, min(p + ivec2(1, 0), last), 0);
  vec4 w = texelFetch(uScene, max(p - ivec2(1, 0), ivec2(0)), 0);
  vec3 cM = m.rgb;
  vec3 cN = n.rgb;
  vec3 cS = s.rgb;
  vec3 cE = e.rgb;
  vec3 cW = w.rgb;
  float lM = luma(cM);
  float lN = luma(cN);
  float lS = luma(cS);
  float lE = luma(cE);
  float lW = luma(cW);
  float lMin = min(lM, min(min(lN, lS), min(lE, lW)));
  float lMax = max(lM, max(max(lN, lS), max(lE, lW)));
  float range = lMax - lMin;
  // Low contrast: keep the pixel. Floor and background are drawn with alpha 0 and are
  // smooth already (the grid shader draws soft lines), so only edges with a solid take part.
  float nearSolid = step(1e-3, max(m.a, max(max(n.a, s.a), max(e.a, w.a))));
  float isEdge = nearSolid * step(max(1.0 / 24.0, lMax * 0.125), range);
  // The edge runs horizontally when the vertical second difference dominates.
  bool horizontal = abs(lN + lS - 2.0 * lM) >= abs(lE + lW - 2.0 * lM);
  vec3 across = horizontal
      ? (abs(lN - lM) >= abs(lS - lM) ? cN : cS)
      : (abs(lE - lM) >= abs(lW - lM) ? cE : cW);
  float sub = clamp(abs(0.25 * (lN + lS + lE + lW) - lM) / max(range, 1e-4), 0.0, 1.0);
  sub = smoothstep(0.0, 1.0, sub);
  float blend = isEdge * sub * sub * 0.5;
  fragColor = vec4(mix(cM, across, blend), m.a);
}
