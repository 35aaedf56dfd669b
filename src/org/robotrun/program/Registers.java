package org.robotrun.program;

import java.util.Arrays;
import java.util.Objects;

/**
 * The controller's register and I/O state (mutable, one per controller): data registers
 * R[1..200], position registers PR[1..100], flags and DI/DO/RI/RO/GI/GO up to their configured
 * sizes ({@link IoRanges}) and TIMER[1..10]. Indices are 1-based as on the pendant; an index out of range throws
 * {@link RegisterIndexException}, which the interpreter reports as an alarm. Call arguments
 * (AR[]) belong to a call frame and live in the interpreter.
 *
 * <p>Data registers keep FANUC's distinction between integer and real values: {@code R[1]=3}
 * holds the integer 3, {@code R[1]=3/2} the real 1.5. Accessors take and return primitives so the
 * interpreter's hot path does not allocate.
 */
public final class Registers {
  public static final int R_COUNT = 200;
  public static final int PR_COUNT = 100;
  public static final int FLAG_COUNT = 200;
  public static final int TIMER_COUNT = 10;
  /** String registers SR[1..25], as on a standard R-30iB. */
  public static final int SR_COUNT = 25;
  /** Longest text a string register holds (the controller's 254 characters). */
  public static final int SR_LENGTH = 254;

  // Package-private so the interpreter's compiled code reads them without per-access checks
  // (it validates indices itself).
  final double[] r = new double[R_COUNT + 1];
  final String[] sr = new String[SR_COUNT + 1];
  final boolean[] rIsInteger = new boolean[R_COUNT + 1];
  final Position[] pr = new Position[PR_COUNT + 1];
  final int[][] io = new int[IoKind.values().length][];
  private final VisionRegisters vision = new VisionRegisters();
  private final double[] timerSec = new double[TIMER_COUNT + 1];
  private final boolean[] timerRunning = new boolean[TIMER_COUNT + 1];

  private final IoRanges ioRanges;

  /** All registers zero (integer 0), PRs Cartesian zero, I/O OFF, timers stopped at 0; default I/O ranges. */
  public Registers() {
    this(IoRanges.DEFAULT);
  }

  /** As {@link #Registers()} with the I/O sizes of {@code ranges}. */
  public Registers(IoRanges ranges) {
    this.ioRanges = Objects.requireNonNull(ranges, "ranges");
    Arrays.fill(rIsInteger, true);
    Arrays.fill(pr, Position.Cartesian.ZERO);
    Arrays.fill(sr, "");
    for (IoKind k : IoKind.values()) {
      io[k.ordinal()] = new int[ranges.size(k) + 1];
    }
  }

  /** The I/O sizes this controller has. */
  /** Vision registers VR[1..10] and the vision processes' pending results. */
  public VisionRegisters vision() {
    return vision;
  }

  public IoRanges ioRanges() {
    return ioRanges;
  }

  /** The highest valid index of {@code kind} on this controller. */
  public int ioSize(IoKind kind) {
    return io[kind.ordinal()].length - 1;
  }

  private static void check(String table, int i, int size) {
    if (i < 1 || i > size) {
      throw new RegisterIndexException(table, i, size);
    }
  }

  // ---- R[] ----

  /** R[i] as a number (integers exactly). */
  public double number(int i) {
    check("R", i, R_COUNT);
    return r[i];
  }

  /** Whether R[i] holds an integer (as opposed to a real). */
  public boolean isInteger(int i) {
    check("R", i, R_COUNT);
    return rIsInteger[i];
  }

  /** Sets R[i] to an integer. */
  public void setInteger(int i, int value) {
    check("R", i, R_COUNT);
    r[i] = value;
    rIsInteger[i] = true;
  }

  /** Sets R[i] to a real. */
  public void setReal(int i, double value) {
    check("R", i, R_COUNT);
    r[i] = value;
    rIsInteger[i] = false;
  }

  /** Sets R[i]; {@code integer} says which kind of number it holds ({@code value} must then be whole). */
  public void set(int i, double value, boolean integer) {
    check("R", i, R_COUNT);
    r[i] = value;
    rIsInteger[i] = integer;
  }

  // ---- PULSE: counted down in the shared I/O, whoever started it ----

  /** Seconds each pulsed port (DO, RO) stays ON; 0 when not pulsing. Made on the first PULSE. */
  private double[][] pulseLeftSec;
  private int activePulses;

  /**
   * Turns {@code kind[i]} ON for {@code widthSec} of simulated time (at least until the next
   * {@link #advancePulses}). The countdown belongs to the I/O, not to the program that started
   * it: a RUN task or action program that ends leaves its pulse to end on time.
   */
  public void startPulse(IoKind kind, int i, double widthSec) {
    if (pulseLeftSec == null) {
      pulseLeftSec = new double[IoKind.values().length][];
    }
    double[] left = pulseLeftSec[kind.ordinal()];
    if (left == null || left.length != io[kind.ordinal()].length) {
      left = pulseLeftSec[kind.ordinal()] = java.util.Arrays.copyOf(left == null ? new double[0] : left,
          io[kind.ordinal()].length);
    }
    io[kind.ordinal()][i] = 1;
    if (left[i] <= 0) {
      activePulses++;
    }
    left[i] = Math.max(widthSec, PULSE_EPS_SEC);
  }

  /** Counts every pending pulse down by {@code dtSec}; a pulse that is over turns its port OFF. Once per tick. */
  public void advancePulses(double dtSec) {
    if (activePulses == 0) {
      return;
    }
    for (int k = 0; k < pulseLeftSec.length; k++) {
      double[] left = pulseLeftSec[k];
      if (left == null) {
        continue;
      }
      for (int i = 1; i < left.length; i++) {
        if (left[i] > 0) {
          left[i] -= dtSec;
          if (left[i] <= PULSE_EPS_SEC) {
            left[i] = 0;
            io[k][i] = 0;
            activePulses--;
          }
        }
      }
    }
  }

  private static final double PULSE_EPS_SEC = 1e-9;

  // ---- SR[] ----

  /** SR[i] as text ("" until set). */
  public String string(int i) {
    check("SR", i, SR_COUNT);
    return sr[i];
  }

  /**
   * Sets SR[i].
   *
   * @throws IllegalArgumentException if the text is longer than {@link #SR_LENGTH}
   */
  public void setString(int i, String value) {
    check("SR", i, SR_COUNT);
    if (value.length() > SR_LENGTH) {
      throw new IllegalArgumentException("SR[" + i + "]: at most " + SR_LENGTH + " characters, got " + value.length());
    }
    sr[i] = value;
  }

  // ---- PR[] ----

  /** PR[i]. */
  public Position position(int i) {
    check("PR", i, PR_COUNT);
    return pr[i];
  }

  /** Sets PR[i]. */
  public void setPosition(int i, Position value) {
    check("PR", i, PR_COUNT);
    pr[i] = Objects.requireNonNull(value, "value");
  }

  // ---- I/O and flags ----

  /** A bit port or flag: ON is true. For GI/GO, whether the group value is non-zero. */
  public boolean bit(IoKind kind, int i) {
    check(kind.name(), i, ioSize(kind));
    return io[kind.ordinal()][i] != 0;
  }

  /** Sets a bit port or flag (inputs too: the simulation writes DI/RI). */
  public void setBit(IoKind kind, int i, boolean on) {
    check(kind.name(), i, ioSize(kind));
    io[kind.ordinal()][i] = on ? 1 : 0;
  }

  /** A port's value as an integer: 0/1 for bits, the group value for GI/GO. */
  public int value(IoKind kind, int i) {
    check(kind.name(), i, ioSize(kind));
    return io[kind.ordinal()][i];
  }

  /** Sets a group port's integer value (GI/GO); for a bit port any non-zero value is ON. */
  public void setValue(IoKind kind, int i, int value) {
    check(kind.name(), i, ioSize(kind));
    io[kind.ordinal()][i] = kind.group() ? value : (value != 0 ? 1 : 0);
  }

  // ---- TIMER[] ----

  /** TIMER[i] in simulated seconds. */
  public double timerSec(int i) {
    check("TIMER", i, TIMER_COUNT);
    return timerSec[i];
  }

  /** Whether TIMER[i] is counting. */
  public boolean timerRunning(int i) {
    check("TIMER", i, TIMER_COUNT);
    return timerRunning[i];
  }

  /** TIMER[i]=START: counts on from its current value. */
  public void startTimer(int i) {
    check("TIMER", i, TIMER_COUNT);
    timerRunning[i] = true;
  }

  /** TIMER[i]=STOP: keeps its value. */
  public void stopTimer(int i) {
    check("TIMER", i, TIMER_COUNT);
    timerRunning[i] = false;
  }

  /** TIMER[i]=RESET: stops it and sets it to 0. */
  public void resetTimer(int i) {
    check("TIMER", i, TIMER_COUNT);
    timerRunning[i] = false;
    timerSec[i] = 0;
  }

  /** Advances every running timer by {@code dtSec} of simulated time. */
  public void advanceTimers(double dtSec) {
    for (int i = 1; i <= TIMER_COUNT; i++) {
      if (timerRunning[i]) {
        timerSec[i] += dtSec;
      }
    }
  }
}
