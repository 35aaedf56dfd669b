package org.robotrun.program;

import java.util.List;
import java.util.Locale;
import java.util.Optional;

/**
 * The controller system variables a TP program may set or read and RobotRun runs (the
 * "parameter name" instruction, {@code $WAITTMOUT=500}). Others are read, kept and written back,
 * and reported as not supported; their lines are skipped.
 *
 * <ul>
 *   <li>{@code $WAITTMOUT}: the timeout of {@code WAIT … TIMEOUT,LBL[n]} in hundredths of a
 *       second (the FANUC R-30iB Operator's Manual: default 3000, i.e. 30 s); an integer 0..32767.
 *   <li>{@code $MCR.$GENOVERRIDE}: the general override in percent, 1..100 (as {@code OVERRIDE=}).
 * </ul>
 */
public final class SystemVariables {
  public static final String WAITTMOUT = "$WAITTMOUT";
  public static final String GENOVERRIDE = "$MCR.$GENOVERRIDE";
  /** The variables RobotRun runs. */
  public static final List<String> SUPPORTED = List.of(WAITTMOUT, GENOVERRIDE);
  /** Largest {@code $WAITTMOUT} (a 16-bit integer on the controller). */
  public static final int MAX_WAITTMOUT = 32767;

  private SystemVariables() {}

  /** The variable's name as RobotRun knows it (upper case), if RobotRun runs it. */
  public static Optional<String> supported(String name) {
    String n = name.toUpperCase(Locale.ROOT);
    return SUPPORTED.contains(n) ? Optional.of(n) : Optional.empty();
  }
}
