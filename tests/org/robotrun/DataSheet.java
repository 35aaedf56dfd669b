package org.robotrun;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Path;

/**
 * The default robot's data-sheet figures, read straight from {@code resources/robots/lrmate200id.json}
 * with a plain JSON parser (not through the product's robot loader), for tests whose expected
 * values are computed from the specification rather than copied from a run.
 */
public final class DataSheet {
  private DataSheet() {}

  /** Maximum joint speeds J1..J6 (deg/s, kinematic joints) as the robot file states them. */
  public static double[] maxSpeedsDegPerSec() {
    try {
      JsonNode robot = new ObjectMapper().readTree(Path.of("resources/robots/lrmate200id.json").toFile());
      double[] v = new double[6];
      for (int i = 0; i < 6; i++) {
        v[i] = robot.get("joints").get(i).get("maxSpeed").asDouble();
      }
      return v;
    } catch (IOException e) {
      throw new UncheckedIOException(e);
    }
  }
}
