package org.robotrun.sim;

import org.robotrun.math.Transform;

/**
 * One thing to draw: a shape placed in WORLD ({@code X_WS}) with a colour (linear RGB, 0..1).
 *
 * @param name what it is, for picking and debugging ("robot1/link3", "table")
 * @param shape the solid
 * @param X_WS the shape's frame in WORLD (mm)
 * @param color red, green, blue, alpha in 0..1
 */
public record DrawItem(String name, DrawShape shape, Transform X_WS, Color color) {

  /** A colour in 0..1 per channel. */
  public record Color(float r, float g, float b, float a) {
    public static Color rgb(double r, double g, double b) {
      return new Color((float) r, (float) g, (float) b, 1f);
    }
  }
}
