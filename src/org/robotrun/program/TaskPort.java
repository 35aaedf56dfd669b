package org.robotrun.program;

import java.util.Optional;

/**
 * How a program reaches the controller's task manager: {@code RUN NAME} asks it to start NAME as
 * a task of its own (multitasking). The interpreter owns this interface so it can be tested
 * without a controller.
 */
@FunctionalInterface
public interface TaskPort {
  /** A port with no multitasking: every RUN is refused. */
  TaskPort NONE = program -> Optional.of("multitasking is not available here");

  /**
   * Starts {@code program} as a new task.
   *
   * @return empty when it started; otherwise why not, as the alarm's message names it (e.g.
   *     "PROG-040 Already locked by other task")
   */
  Optional<String> run(String program);

  /**
   * A WARN alarm a program raised (a RUN the controller refused): the program went on; the
   * controller keeps and shows it (docs/alarms.md). A port without a controller drops it.
   */
  default void warning(Alarm alarm) {
  }

  /**
   * The state of background-logic slot {@code slot} (1-based) as {@code $MIX_BG[slot].$STATUS}
   * reads it: 2 running, 1 stopped, 0 no program in the slot (see SystemVariables).
   */
  default int backgroundStatus(int slot) {
    return 0;
  }
}
