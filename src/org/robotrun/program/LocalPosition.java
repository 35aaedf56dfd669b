package org.robotrun.program;

import java.util.Objects;

/**
 * A program's local position {@code P[n:"comment"]} as its /POS block holds it: taught in user
 * frame {@code userFrame} and tool frame {@code toolFrame} (0 = world / flange). A Cartesian
 * P[] run with other active frames is a frame-mismatch alarm, as on the controller.
 */
public record LocalPosition(int number, String comment, int userFrame, int toolFrame, Position position) {
  public LocalPosition {
    Objects.requireNonNull(comment, "comment");
    Objects.requireNonNull(position, "position");
    if (number < 1) {
      throw new IllegalArgumentException("P[" + number + "]: position numbers start at 1");
    }
  }
}
