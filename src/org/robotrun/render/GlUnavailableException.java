package org.robotrun.render;

/** No OpenGL context could be created; the message says why and what to install. */
public final class GlUnavailableException extends RuntimeException {
  private final boolean noGl33Context;

  public GlUnavailableException(String message) {
    this(message, false);
  }

  /**
   * @param noGl33Context the display works but its driver gave no OpenGL 3.3 core context (a
   *     software renderer may still give one)
   */
  public GlUnavailableException(String message, boolean noGl33Context) {
    super(message);
    this.noGl33Context = noGl33Context;
  }

  /** Whether the display worked and only the OpenGL 3.3 core context was refused. */
  public boolean noGl33Context() {
    return noGl33Context;
  }
}
