package org.robotrun.program;

import java.util.Map;

/**
 * Controller settings the interpreter reads (FANUC system variables in brackets).
 *
 * @param instructionBudgetPerTick lines a program may run in one tick without motion or wait
 *     before it is a runaway loop alarm
 * @param maxCallDepth deepest CALL nesting (the top program counts as 1)
 * @param waitTimeoutSec {@code WAIT … TIMEOUT,LBL[n]} timeout in seconds ($WAITTMOUT)
 * @param defaultPulseSec pulse width of {@code DO[i]=PULSE} without a width ($DEFPULSE)
 * @param userAlarmMessages UALM[i] texts ($UALRM_MSG[i]); missing ones show "UALM[i]"
 * @param ioRanges the controller's I/O index ranges (its registers are made with them)
 * @param macros the controller's macro table (MENU &gt; SETUP &gt; Macro): macro name in upper case
 *     with single spaces ("HAND1 OPEN") to the program it runs
 */
public record InterpreterSettings(int instructionBudgetPerTick, int maxCallDepth, double waitTimeoutSec,
    double defaultPulseSec, Map<Integer, String> userAlarmMessages, IoRanges ioRanges, Map<String, String> macros) {

  public InterpreterSettings(int instructionBudgetPerTick, int maxCallDepth, double waitTimeoutSec,
      double defaultPulseSec, Map<Integer, String> userAlarmMessages, IoRanges ioRanges) {
    this(instructionBudgetPerTick, maxCallDepth, waitTimeoutSec, defaultPulseSec, userAlarmMessages, ioRanges, Map.of());
  }

  public InterpreterSettings(int instructionBudgetPerTick, int maxCallDepth, double waitTimeoutSec,
      double defaultPulseSec, Map<Integer, String> userAlarmMessages) {
    this(instructionBudgetPerTick, maxCallDepth, waitTimeoutSec, defaultPulseSec, userAlarmMessages, IoRanges.DEFAULT);
  }

  public InterpreterSettings {
    if (instructionBudgetPerTick < 1) {
      throw new IllegalArgumentException("instructionBudgetPerTick must be >= 1, got " + instructionBudgetPerTick);
    }
    if (maxCallDepth < 1) {
      throw new IllegalArgumentException("maxCallDepth must be >= 1, got " + maxCallDepth);
    }
    userAlarmMessages = Map.copyOf(userAlarmMessages);
    java.util.Objects.requireNonNull(ioRanges, "ioRanges");
    Map<String, String> m = new java.util.LinkedHashMap<>();
    macros.forEach((k, v) -> m.put(macroKey(k), v));
    macros = java.util.Collections.unmodifiableMap(m);
  }

  /** A macro name as the table keys it: upper case, words separated by one space. */
  public static String macroKey(String name) {
    return String.join(" ", name.trim().toUpperCase(java.util.Locale.ROOT).split("\\s+"));
  }

  /** These settings with the macro table {@code table} (macro name to program). */
  public InterpreterSettings withMacros(Map<String, String> table) {
    return new InterpreterSettings(instructionBudgetPerTick, maxCallDepth, waitTimeoutSec, defaultPulseSec,
        userAlarmMessages, ioRanges, table);
  }

  /** 100 000 lines per tick, depth 32, $WAITTMOUT 30 s, $DEFPULSE 0.4 s, no UALM texts, default I/O ranges. */
  public static InterpreterSettings defaults() {
    return new InterpreterSettings(100_000, 32, 30.0, 0.4, Map.of());
  }

  public InterpreterSettings withBudget(int budget) {
    return new InterpreterSettings(budget, maxCallDepth, waitTimeoutSec, defaultPulseSec, userAlarmMessages, ioRanges, macros);
  }

  public InterpreterSettings withWaitTimeoutSec(double seconds) {
    return new InterpreterSettings(instructionBudgetPerTick, maxCallDepth, seconds, defaultPulseSec, userAlarmMessages, ioRanges, macros);
  }

  public InterpreterSettings withUserAlarmMessages(Map<Integer, String> messages) {
    return new InterpreterSettings(instructionBudgetPerTick, maxCallDepth, waitTimeoutSec, defaultPulseSec, messages, ioRanges, macros);
  }

  public InterpreterSettings withIoRanges(IoRanges ranges) {
    return new InterpreterSettings(instructionBudgetPerTick, maxCallDepth, waitTimeoutSec, defaultPulseSec,
        userAlarmMessages, ranges, macros);
  }
}
