package org.robotrun.render;

/**
 * How the renderer smooths edges. Measured with {@code robotrun bench render} on Mesa's
 * llvmpipe (1280x800): {@link #MSAA4} costs about three times the CPU of {@link #FXAA}, because
 * llvmpipe tests depth, stores colour and clears per sample and then needs a resolve pass;
 * the FXAA post pass reads the finished frame once.
 */
public enum AntiAliasing {
  /** No smoothing: hard, stair-stepped silhouettes. */
  NONE(0),
  /** One sample per pixel, then an edge-directed blur post pass ({@code shaders/fxaa.frag}). */
  FXAA(0),
  /** Four samples per pixel, resolved by a blit. */
  MSAA4(4);

  /** The default everywhere (headless and window), so a screenshot looks like the window. */
  public static final AntiAliasing DEFAULT = FXAA;

  private final int samples;

  AntiAliasing(int samples) {
    this.samples = samples;
  }

  /**
   * Samples per pixel of the framebuffer the scene is drawn into, as GL and GLFW count them:
   * 0 for an ordinary (not multisampled) framebuffer.
   */
  public int samples() {
    return samples;
  }
}
