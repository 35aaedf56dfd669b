package org.robotrun.sim;

/**
 * The controller's mode switch (operator panel key switch), as on an R-30iB.
 *
 * <ul>
 *   <li>{@link #T1}: teach, reduced speed: the TCP and the flange never exceed
 *       {@link #T1_SPEED_MM_PER_SEC}, jogs and programs alike; programs run only while SHIFT and
 *       DEADMAN are held on an enabled pendant (hold-to-run).
 *   <li>{@link #T2}: teach at programmed speed, hold-to-run.
 *   <li>{@link #AUTO}: programs start from the operator panel (CYCLE START) with the pendant
 *       disabled; the pendant cannot jog. Headless {@code robotrun run} runs in AUTO.
 * </ul>
 */
public enum OperatingMode {
  T1, T2, AUTO;

  /** T1 speed limit of the TCP and the flange (ISO 10218-1 reduced speed), mm/s. */
  public static final double T1_SPEED_MM_PER_SEC = 250;

  /** Whether programs run only while SHIFT and DEADMAN are held (T1, T2). */
  public boolean holdToRun() {
    return this != AUTO;
  }
}
