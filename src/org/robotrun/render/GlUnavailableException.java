package org.robotrun.render;

/** No OpenGL context could be created; the message says why and what to install. */
public final class GlUnavailableException extends RuntimeException {
  public GlUnavailableException(String message) {
    super(message);
  }
}
