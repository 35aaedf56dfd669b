package org.robotrun.program;

/**
 * What an alarm does to the program and the arm, as a FANUC controller's severities do (the
 * local/global variants .L/.G collapse here: the simulator runs one program per robot).
 */
public enum AlarmSeverity {
  /** A warning: the program goes on, the arm keeps moving. */
  WARN("the program goes on; nothing stops"),
  /** The program pauses; the arm decelerates to a stop. RESET, then SHIFT+FWD resumes. */
  PAUSE("the program pauses; the arm decelerates to a stop"),
  /** The program pauses; the arm decelerates to a stop along its path. RESET, then SHIFT+FWD resumes. */
  STOP("the program pauses; the arm decelerates to a stop"),
  /** Servo power off: the arm stops at once, the program pauses. RESET (E-stop released), then SHIFT+FWD resumes. */
  SERVO("servo power off: the arm stops at once and the program pauses"),
  /** The program ends (ABORTED); the arm stops. */
  ABORT("the program is aborted and the arm stops");

  private final String effect;

  AlarmSeverity(String effect) {
    this.effect = effect;
  }

  /** What happens, in words for the alarm detail page. */
  public String effect() {
    return effect;
  }
}
