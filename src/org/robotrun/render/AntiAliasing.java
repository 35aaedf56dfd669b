package org.robotrun.render;

/**
 * How the renderer smooths edges. Measured with {@code robotrun bench render} on Mesa's
 * llvmpipe (1280x800, default scene, CPU time per frame): {@link #NONE} 14 ms, {@link #FXAA}
 * 16 ms, {@link #MSAA4} 40 ms, because llvmpipe tests depth, stores colour and clears per
 * sample and then needs a resolve pass, while the FXAA pass only rereads the robot's part of
 * the finished frame.
 */
public enum AntiAliasing {
  /** No smoothing: hard, stair-stepped silhouettes. */
  NONE(0),
  /**
   * One sample per pixel, then a pass that blends pixels across the solids' edges
   * ({@link FxaaPass}, {@code shaders/fxaa.frag}).
   */
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
