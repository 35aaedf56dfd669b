package org.robotrun.program;

import java.util.Objects;
import org.robotrun.math.Xyzwpr;

/**
 * A position as a program or a position register holds it: Cartesian (XYZWPR in mm and degrees,
 * as the pendant and .LS files show it, plus a CONFIG) or joint (J1..J6 in degrees, FANUC's
 * coupled J3 convention). Values are kept as read so a round trip is lossless; convert to
 * radians once with {@link Cartesian#toXyzwpr()}.
 */
public sealed interface Position {

  /** Number of elements addressable as {@code PR[i,j]}: always 6. */
  int ELEMENTS = 6;

  /** Element j = 1..6 (X, Y, Z, W, P, R or J1..J6). */
  double element(int j);

  /** A copy with element j = 1..6 replaced. */
  Position withElement(int j, double value);

  /** Cartesian XYZWPR (mm, deg) with its configuration. */
  record Cartesian(double xMm, double yMm, double zMm, double wDeg, double pDeg, double rDeg, Config config)
      implements Position {
    public Cartesian {
      Objects.requireNonNull(config, "config");
    }

    /** All zeros in the default configuration, as a fresh PR reads on the pendant. */
    public static final Cartesian ZERO = new Cartesian(0, 0, 0, 0, 0, 0, Config.DEFAULT);

    /** The pose in the math package's convention (mm, radians). */
    public Xyzwpr toXyzwpr() {
      return Xyzwpr.ofDegrees(xMm, yMm, zMm, wDeg, pDeg, rDeg);
    }

    /** From a pose in mm/radians. */
    public static Cartesian of(Xyzwpr pose, Config config) {
      return new Cartesian(pose.x(), pose.y(), pose.z(), pose.wDeg(), pose.pDeg(), pose.rDeg(), config);
    }

    @Override
    public double element(int j) {
      return switch (j) {
        case 1 -> xMm;
        case 2 -> yMm;
        case 3 -> zMm;
        case 4 -> wDeg;
        case 5 -> pDeg;
        case 6 -> rDeg;
        default -> throw new IndexOutOfBoundsException("position element " + j + " (expected 1..6)");
      };
    }

    @Override
    public Cartesian withElement(int j, double v) {
      return switch (j) {
        case 1 -> new Cartesian(v, yMm, zMm, wDeg, pDeg, rDeg, config);
        case 2 -> new Cartesian(xMm, v, zMm, wDeg, pDeg, rDeg, config);
        case 3 -> new Cartesian(xMm, yMm, v, wDeg, pDeg, rDeg, config);
        case 4 -> new Cartesian(xMm, yMm, zMm, v, pDeg, rDeg, config);
        case 5 -> new Cartesian(xMm, yMm, zMm, wDeg, v, rDeg, config);
        case 6 -> new Cartesian(xMm, yMm, zMm, wDeg, pDeg, v, config);
        default -> throw new IndexOutOfBoundsException("position element " + j + " (expected 1..6)");
      };
    }

    /** Element-wise sum, as {@code PR[i]=PR[j]+PR[k]} computes it; keeps this config. */
    public Cartesian plus(Cartesian o) {
      return new Cartesian(xMm + o.xMm, yMm + o.yMm, zMm + o.zMm, wDeg + o.wDeg, pDeg + o.pDeg, rDeg + o.rDeg, config);
    }

    /** Element-wise difference, as {@code PR[i]=PR[j]-PR[k]} computes it; keeps this config. */
    public Cartesian minus(Cartesian o) {
      return new Cartesian(xMm - o.xMm, yMm - o.yMm, zMm - o.zMm, wDeg - o.wDeg, pDeg - o.pDeg, rDeg - o.rDeg, config);
    }
  }

  /** Joint angles J1..J6 in degrees (pendant convention: FANUC's coupled J3). */
  record Joint(double j1Deg, double j2Deg, double j3Deg, double j4Deg, double j5Deg, double j6Deg)
      implements Position {

    /** All joints at zero. */
    public static final Joint ZERO = new Joint(0, 0, 0, 0, 0, 0);

    @Override
    public double element(int j) {
      return switch (j) {
        case 1 -> j1Deg;
        case 2 -> j2Deg;
        case 3 -> j3Deg;
        case 4 -> j4Deg;
        case 5 -> j5Deg;
        case 6 -> j6Deg;
        default -> throw new IndexOutOfBoundsException("joint element " + j + " (expected 1..6)");
      };
    }

    @Override
    public Joint withElement(int j, double v) {
      return switch (j) {
        case 1 -> new Joint(v, j2Deg, j3Deg, j4Deg, j5Deg, j6Deg);
        case 2 -> new Joint(j1Deg, v, j3Deg, j4Deg, j5Deg, j6Deg);
        case 3 -> new Joint(j1Deg, j2Deg, v, j4Deg, j5Deg, j6Deg);
        case 4 -> new Joint(j1Deg, j2Deg, j3Deg, v, j5Deg, j6Deg);
        case 5 -> new Joint(j1Deg, j2Deg, j3Deg, j4Deg, v, j6Deg);
        case 6 -> new Joint(j1Deg, j2Deg, j3Deg, j4Deg, j5Deg, v);
        default -> throw new IndexOutOfBoundsException("joint element " + j + " (expected 1..6)");
      };
    }

    /** Element-wise sum. */
    public Joint plus(Joint o) {
      return new Joint(j1Deg + o.j1Deg, j2Deg + o.j2Deg, j3Deg + o.j3Deg, j4Deg + o.j4Deg, j5Deg + o.j5Deg, j6Deg + o.j6Deg);
    }

    /** Element-wise difference. */
    public Joint minus(Joint o) {
      return new Joint(j1Deg - o.j1Deg, j2Deg - o.j2Deg, j3Deg - o.j3Deg, j4Deg - o.j4Deg, j5Deg - o.j5Deg, j6Deg - o.j6Deg);
    }
  }
}
