package org.robotrun.collision;

/**
 * The separating-axis test for two oriented boxes: they are disjoint iff their projections
 * onto one of 15 axes are disjoint — the 3 face normals of each box and the 9 cross products
 * of an edge direction of one with an edge direction of the other.
 *
 * <p>Formulation after S. Gottschalk, M. Lin, D. Manocha, "OBBTree" (SIGGRAPH 1996), as written
 * out in C. Ericson, <i>Real-Time Collision Detection</i> (2005), §4.4.1: everything is
 * expressed in box A's frame, {@code R[i][j] = a_i · b_j}, and {@link #PARALLEL_EPS} is added
 * to {@code |R|} so that a cross axis of (nearly) parallel edges, whose length is only rounding
 * noise, can never claim a separation that the face axes would not.
 *
 * <p><b>Touching counts as overlap.</b> Boxes are closed sets, and a gap of up to
 * {@link #CONTACT_TOLERANCE_MM} along the separating axis also counts as contact, so a part
 * resting exactly on a table top, or a link whose FK rounding leaves a 1e-13 mm gap, is
 * reported the same way every time. Boxes separated by more than the tolerance along one of
 * the 15 axes are disjoint.
 *
 * <p>The hot path {@link #overlap(double[], int, double[], int)} reads boxes from flat arrays
 * and allocates nothing; exits at the first separating axis.
 */
public final class SeparatingAxisTest {
  /** A gap up to this size (mm) along the separating axis still counts as touching. */
  public static final double CONTACT_TOLERANCE_MM = 1e-6;

  /** Added to |R[i][j]| against rounding when edges are parallel (Ericson §4.4.1). */
  static final double PARALLEL_EPS = 1e-12;

  private static final double TOL = CONTACT_TOLERANCE_MM;
  private static final double TOL2 = TOL * TOL;

  private SeparatingAxisTest() {}

  /**
   * Whether the two boxes overlap or touch. Copies both boxes into a small array first; loops
   * over many boxes should keep them in flat arrays and call
   * {@link #overlap(double[], int, double[], int)}.
   */
  public static boolean overlap(Obb a, Obb b) {
    double[] both = new double[2 * Obb.STRIDE];
    a.writeTo(both, 0);
    b.writeTo(both, 1);
    return overlap(both, 0, both, 1);
  }

  /**
   * Whether box {@code ia} of {@code a} and box {@code ib} of {@code b} overlap or touch; the
   * arrays hold {@link Obb#STRIDE} doubles per box in {@link Obb#writeTo} order.
   */
  public static boolean overlap(double[] a, int ia, double[] b, int ib) {
    int i = ia * Obb.STRIDE;
    int j = ib * Obb.STRIDE;
    // Loaded into locals once: centre, half extents, row-major rotation (columns = box axes).
    double acx = a[i], acy = a[i + 1], acz = a[i + 2];
    double ae0 = a[i + 3], ae1 = a[i + 4], ae2 = a[i + 5];
    double a00 = a[i + 6], a01 = a[i + 7], a02 = a[i + 8];
    double a10 = a[i + 9], a11 = a[i + 10], a12 = a[i + 11];
    double a20 = a[i + 12], a21 = a[i + 13], a22 = a[i + 14];
    double bcx = b[j], bcy = b[j + 1], bcz = b[j + 2];
    double be0 = b[j + 3], be1 = b[j + 4], be2 = b[j + 5];
    double b00 = b[j + 6], b01 = b[j + 7], b02 = b[j + 8];
    double b10 = b[j + 9], b11 = b[j + 10], b12 = b[j + 11];
    double b20 = b[j + 12], b21 = b[j + 13], b22 = b[j + 14];
    // R[i][j] = A axis i · B axis j (axes are the columns of each rotation).
    double r00 = a00 * b00 + a10 * b10 + a20 * b20;
    double r01 = a00 * b01 + a10 * b11 + a20 * b21;
    double r02 = a00 * b02 + a10 * b12 + a20 * b22;
    double r10 = a01 * b00 + a11 * b10 + a21 * b20;
    double r11 = a01 * b01 + a11 * b11 + a21 * b21;
    double r12 = a01 * b02 + a11 * b12 + a21 * b22;
    double r20 = a02 * b00 + a12 * b10 + a22 * b20;
    double r21 = a02 * b01 + a12 * b11 + a22 * b21;
    double r22 = a02 * b02 + a12 * b12 + a22 * b22;

    // Centre offset, in A's frame.
    double dx = bcx - acx, dy = bcy - acy, dz = bcz - acz;
    double t0 = a00 * dx + a10 * dy + a20 * dz;
    double t1 = a01 * dx + a11 * dy + a21 * dz;
    double t2 = a02 * dx + a12 * dy + a22 * dz;

    double q00 = Math.abs(r00) + PARALLEL_EPS, q01 = Math.abs(r01) + PARALLEL_EPS, q02 = Math.abs(r02) + PARALLEL_EPS;
    double q10 = Math.abs(r10) + PARALLEL_EPS, q11 = Math.abs(r11) + PARALLEL_EPS, q12 = Math.abs(r12) + PARALLEL_EPS;
    double q20 = Math.abs(r20) + PARALLEL_EPS, q21 = Math.abs(r21) + PARALLEL_EPS, q22 = Math.abs(r22) + PARALLEL_EPS;

    // A's face normals (unit axes).
    if (Math.abs(t0) - (ae0 + be0 * q00 + be1 * q01 + be2 * q02) > TOL) {
      return false;
    }
    if (Math.abs(t1) - (ae1 + be0 * q10 + be1 * q11 + be2 * q12) > TOL) {
      return false;
    }
    if (Math.abs(t2) - (ae2 + be0 * q20 + be1 * q21 + be2 * q22) > TOL) {
      return false;
    }
    // B's face normals (unit axes).
    if (Math.abs(t0 * r00 + t1 * r10 + t2 * r20) - (ae0 * q00 + ae1 * q10 + ae2 * q20 + be0) > TOL) {
      return false;
    }
    if (Math.abs(t0 * r01 + t1 * r11 + t2 * r21) - (ae0 * q01 + ae1 * q11 + ae2 * q21 + be1) > TOL) {
      return false;
    }
    if (Math.abs(t0 * r02 + t1 * r12 + t2 * r22) - (ae0 * q02 + ae1 * q12 + ae2 * q22 + be2) > TOL) {
      return false;
    }
    // Edge × edge axes A_i × B_j; their length is sqrt(1 - R[i][j]^2), used only to scale the
    // contact tolerance once a gap has been found.
    if (crossSeparates(Math.abs(t2 * r10 - t1 * r20) - (ae1 * q20 + ae2 * q10 + be1 * q02 + be2 * q01), r00)) {
      return false;
    }
    if (crossSeparates(Math.abs(t2 * r11 - t1 * r21) - (ae1 * q21 + ae2 * q11 + be0 * q02 + be2 * q00), r01)) {
      return false;
    }
    if (crossSeparates(Math.abs(t2 * r12 - t1 * r22) - (ae1 * q22 + ae2 * q12 + be0 * q01 + be1 * q00), r02)) {
      return false;
    }
    if (crossSeparates(Math.abs(t0 * r20 - t2 * r00) - (ae0 * q20 + ae2 * q00 + be1 * q12 + be2 * q11), r10)) {
      return false;
    }
    if (crossSeparates(Math.abs(t0 * r21 - t2 * r01) - (ae0 * q21 + ae2 * q01 + be0 * q12 + be2 * q10), r11)) {
      return false;
    }
    if (crossSeparates(Math.abs(t0 * r22 - t2 * r02) - (ae0 * q22 + ae2 * q02 + be0 * q11 + be1 * q10), r12)) {
      return false;
    }
    if (crossSeparates(Math.abs(t1 * r00 - t0 * r10) - (ae0 * q10 + ae1 * q00 + be1 * q22 + be2 * q21), r20)) {
      return false;
    }
    if (crossSeparates(Math.abs(t1 * r01 - t0 * r11) - (ae0 * q11 + ae1 * q01 + be0 * q22 + be2 * q20), r21)) {
      return false;
    }
    return !crossSeparates(Math.abs(t1 * r02 - t0 * r12) - (ae0 * q12 + ae1 * q02 + be0 * q21 + be1 * q20), r22);
  }

  /**
   * Whether a gap {@code d} measured along the unnormalised axis A_i × B_j (length
   * sqrt(1 − r²), r = A_i · B_j) exceeds the contact tolerance.
   */
  private static boolean crossSeparates(double d, double r) {
    return d > 0 && d * d > TOL2 * (1 - r * r);
  }
}
