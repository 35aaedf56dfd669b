package org.robotrun.render;

import org.junit.jupiter.api.Assumptions;

/**
 * Render tests need OpenGL. Outside CI a machine without Mesa skips them and says so; with
 * {@code CI=true} they never skip: a missing OpenGL fails the build.
 */
public final class GlTestSupport {
  private GlTestSupport() {}

  public static HeadlessRenderer rendererOrSkip(int width, int height) {
    return rendererOrSkip(width, height, AntiAliasing.DEFAULT);
  }

  public static HeadlessRenderer rendererOrSkip(int width, int height, AntiAliasing antiAliasing) {
    try {
      return new HeadlessRenderer(width, height, antiAliasing);
    } catch (GlUnavailableException e) {
      if ("true".equals(System.getenv("CI"))) {
        throw new AssertionError("CI must render for real, but: " + e.getMessage(), e);
      }
      Assumptions.abort("skipped: no headless OpenGL on this machine (" + e.getMessage() + ")");
      throw e;
    }
  }
}
