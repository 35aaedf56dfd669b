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
 *   <li>{@code $MNUTOOLNUM[1]}, {@code $MNUFRAMENUM[1]}: the active tool and user frame numbers of
 *       motion group 1 (what {@code UTOOL_NUM=} and {@code UFRAME_NUM=} set); setting them selects
 *       the frame as those statements do.
 *   <li>{@code $JCR.$JOG_GP}: the motion group the pendant jogs; read only here, always 1 (a
 *       RobotRun robot is one motion group).
 *   <li>{@code $MIX_BG[n].$STATUS}: the state of background-logic slot n, read only: 2 running,
 *       1 stopped, 0 no program in the slot. (RobotRun's reading of the values, from how
 *       programs in the field test them; docs/tp-language.md says so.)
 * </ul>
 *
 * <p>Any other variable is read and written back as written; a line that reads it, or sets it in
 * an expression, is reported {@code not supported} naming the variable and alarms when it runs.
 */
public final class SystemVariables {
  public static final String WAITTMOUT = "$WAITTMOUT";
  public static final String GENOVERRIDE = "$MCR.$GENOVERRIDE";
  public static final String TOOLNUM = "$MNUTOOLNUM[1]";
  public static final String FRAMENUM = "$MNUFRAMENUM[1]";
  public static final String JOG_GROUP = "$JCR.$JOG_GP";
  /** The variables RobotRun runs. */
  public static final List<String> SUPPORTED = List.of(WAITTMOUT, GENOVERRIDE, TOOLNUM, FRAMENUM, JOG_GROUP);
  /** The ones a program may set. */
  public static final List<String> WRITABLE = List.of(WAITTMOUT, GENOVERRIDE, TOOLNUM, FRAMENUM);
  /** Largest {@code $WAITTMOUT} (a 16-bit integer on the controller). */
  public static final int MAX_WAITTMOUT = 32767;

  private SystemVariables() {}

  /** The variable's name as RobotRun knows it (upper case), if RobotRun runs it. */
  public static Optional<String> supported(String name) {
    String n = name.toUpperCase(Locale.ROOT);
    return SUPPORTED.contains(n) || backgroundSlot(n) > 0 ? Optional.of(n) : Optional.empty();
  }

  /** n of {@code $MIX_BG[n].$STATUS} (upper case), else 0. */
  public static int backgroundSlot(String name) {
    if (!name.startsWith("$MIX_BG[") || !name.endsWith("].$STATUS")) {
      return 0;
    }
    String digits = name.substring("$MIX_BG[".length(), name.length() - "].$STATUS".length());
    if (digits.isEmpty() || digits.length() > 3 || !digits.chars().allMatch(Character::isDigit)) {
      return 0;
    }
    return Integer.parseInt(digits);
  }

  /** The variable's name as RobotRun knows it (upper case), if a program may set it here. */
  public static Optional<String> writable(String name) {
    String n = name.toUpperCase(Locale.ROOT);
    return WRITABLE.contains(n) ? Optional.of(n) : Optional.empty();
  }
}
