package org.robotrun.app;

import java.io.PrintStream;
import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.time.Instant;
import java.util.Locale;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.atomic.AtomicReference;
import org.robotrun.control.RobotControl;
import org.robotrun.pendant.Key;
import org.robotrun.pendant.Pendant;

/**
 * The window side of {@code robotrun bench window}: drives a running window (a {@link GuiCommand}
 * session) through its phases and prints what each cost. After a settling time it stays idle,
 * then jogs J1 back and forth through the pendant (TP ENABLE, DEADMAN, SHIFT and a jog key, as a
 * student's keys do), then runs a program of the cell from the pendant (SELECT, SHIFT+FWD; at its
 * end the scene is reset and it starts again from line 1), each for the same time, and then asks
 * the window to close as its close button does.
 *
 * <p>A timer thread takes the figures at each phase's edges, so taking them never wakes an idle
 * window; what the pendant does happens on the window's thread, after a frame. Per phase it prints
 * {@code phase=NAME fps=F cpu_pct=P frame_cpu_ms=M frames=N seconds=S load=L} on stdout, where
 * cpu_pct is the process's CPU time over the phase (every thread: GC, JIT and Mesa's own) in % of
 * one core and frame_cpu_ms the CPU time per drawn frame of the window's thread and Mesa's
 * rendering threads, less the time the window's thread spent stepping the simulation ({@code -}
 * when no frame was drawn). At the close request it prints {@code close_requested_epoch_us=T},
 * so that the process which started this one can time the rest from outside.
 */
final class WindowBench {
  /** After the first frame: start-up's compiling and the window's first frames settle. */
  private static final double SETTLE_SEC = 2.0;
  /** Before a moving phase is timed: the first jog or run (compiling its code paths) is not timed. */
  private static final double LEAD_IN_SEC = 1.0;
  /** A jog key is held this long, then the opposite one (J1 stays far from its limits). */
  private static final double JOG_SWING_SEC = 1.5;

  enum Phase { SETTLE, IDLE, JOG, RUN, CLOSE }

  private final GuiCommand.Session session;
  private final double seconds;
  private final String program;
  private final PrintStream out;
  private final AtomicLong simCpuNanos = new AtomicLong();
  /** The phase the timer thread asked for; the window thread acts on it after its next frame. */
  private final AtomicReference<Phase> wanted = new AtomicReference<>(Phase.SETTLE);
  private Phase acted = Phase.SETTLE;
  private volatile Thread windowThread;
  private final ThreadMXBean threads = ManagementFactory.getThreadMXBean();
  private long jogSince;
  private int jogSign = 1;
  private volatile String problem = "";

  WindowBench(GuiCommand.Session session, double seconds, String program, PrintStream out) {
    this.session = session;
    this.seconds = seconds;
    this.program = program;
    this.out = out;
  }

  /** CPU time (ns) the window's thread spent stepping the simulation; GuiCommand.run adds to it. */
  AtomicLong simCpuNanos() {
    return simCpuNanos;
  }

  /** What went wrong while driving the window ("" when nothing did). */
  String problem() {
    return problem;
  }

  /** Installs the per-frame handler; call before the window runs. */
  void install() {
    session.window().setAfterFrameHandler(this::afterFrame);
  }

  private void afterFrame() {
    if (windowThread == null) {
      windowThread = Thread.currentThread();
      Thread timer = new Thread(this::timeline, "bench-window-timer");
      timer.setDaemon(true);
      timer.start();
    }
    Phase p = wanted.get();
    if (p != acted) {
      acted = p;
      begin(p);
    }
    try {
      if (p == Phase.JOG) {
        swingJog();
      } else if (p == Phase.RUN) {
        keepRunning();
      }
    } catch (RuntimeException e) {
      fail("bench window: " + e);
    }
  }

  private Pendant pendant() {
    return session.robots().get();
  }

  /** Starts a phase's actions (window thread). */
  private void begin(Phase p) {
    Pendant pd = pendant();
    switch (p) {
      case SETTLE, IDLE -> {}
      case JOG -> {
        pd.setTpEnabled(true);
        pd.press(Key.DEADMAN);
        pd.press(Key.SHIFT);
        pd.press(Key.JOG_PLUS_1);
        jogSince = System.nanoTime();
        if (session.controller().jogDirection(1) == 0) {
          fail("bench window: the jog did not start: " + pd.message());
        }
      }
      case RUN -> {
        pd.release(jogSign > 0 ? Key.JOG_PLUS_1 : Key.JOG_MINUS_1);
        int index = pd.control().programNames().indexOf(program);
        if (index < 0) {
          fail("bench window: the cell has no program " + program + " (it has " + pd.control().programNames() + ")");
          return;
        }
        pd.tap(Key.SELECT);
        for (int i = 0; i < index; i++) {
          pd.tap(Key.DOWN);
        }
        pd.tap(Key.ENTER);
        start(pd);
      }
      case CLOSE -> {
        pd.release(Key.SHIFT);
        pd.release(Key.DEADMAN);
        session.window().closeButton();
      }
    }
  }

  /** Holds +J1, then -J1, in turns. */
  private void swingJog() {
    if (System.nanoTime() - jogSince < JOG_SWING_SEC * 1e9) {
      return;
    }
    Pendant pd = pendant();
    pd.release(jogSign > 0 ? Key.JOG_PLUS_1 : Key.JOG_MINUS_1);
    jogSign = -jogSign;
    pd.press(jogSign > 0 ? Key.JOG_PLUS_1 : Key.JOG_MINUS_1);
    jogSince = System.nanoTime();
  }

  /** A program that ended starts again from line 1, the parts back where they began. */
  private void keepRunning() {
    RobotControl.ExecutionStatus st = pendant().control().status();
    if (st.state() == RobotControl.ExecState.RUNNING) {
      return;
    }
    session.sim().resetScene();
    Pendant pd = pendant();
    // SHIFT is held: UP pages up to the first line
    for (int i = 0; i < 20; i++) {
      pd.tap(Key.UP);
    }
    start(pd);
  }

  /** SHIFT+FWD on the selected program (DEADMAN and SHIFT are held). */
  private void start(Pendant pd) {
    pd.press(Key.FWD);
    pd.release(Key.FWD);
    if (pd.control().status().state() != RobotControl.ExecState.RUNNING) {
      fail("bench window: " + program + " did not start: " + pd.message());
    }
  }

  private void fail(String why) {
    if (problem.isEmpty()) {
      problem = why;
    }
    wanted.set(Phase.CLOSE);
    acted = Phase.CLOSE;
    session.window().requestClose();
  }

  /** The timer thread: phase edges by the clock, figures taken there. */
  private void timeline() {
    long t = System.nanoTime();
    sleepUntil(t += (long) (SETTLE_SEC * 1e9));
    if (!problem.isEmpty()) {
      return;
    }
    Sample s = sample();
    enter(Phase.IDLE);
    sleepUntil(t += (long) (seconds * 1e9));
    Sample e = sample();
    report("idle", s, e);
    for (Phase p : new Phase[] {Phase.JOG, Phase.RUN}) {
      enter(p);
      sleepUntil(t += (long) (LEAD_IN_SEC * 1e9));
      s = sample();
      sleepUntil(t += (long) (seconds * 1e9));
      e = sample();
      if (!problem.isEmpty()) {
        return;
      }
      report(p == Phase.JOG ? "jog" : "run", s, e);
    }
    out.println("close_requested_epoch_us=" + epochMicros(Instant.now()));
    out.flush();
    enter(Phase.CLOSE);
  }

  /** Asks the window thread for a phase and wakes it (it may be asleep waiting for input). */
  private void enter(Phase p) {
    wanted.set(p);
    org.lwjgl.glfw.GLFW.glfwPostEmptyEvent();
  }

  private static void sleepUntil(long nanoTime) {
    for (long left; (left = nanoTime - System.nanoTime()) > 0; ) {
      try {
        Thread.sleep(left / 1_000_000, (int) (left % 1_000_000));
      } catch (InterruptedException e) {
        Thread.currentThread().interrupt();
        return;
      }
    }
  }

  static long epochMicros(Instant i) {
    return i.getEpochSecond() * 1_000_000L + i.getNano() / 1000;
  }

  /** The figures at one instant. */
  private record Sample(long nanos, long frames, long processCpu, long windowCpu, long glCpu, long simCpu, long[] parts,
      long damaged) {}

  private Sample sample() {
    return new Sample(System.nanoTime(), session.window().frames(), ProcessCpu.processNanos(),
        threads.getThreadCpuTime(windowThread.threadId()), ProcessCpu.nativeThreadsNanos(ProcessCpu.GL_THREADS),
        simCpuNanos.get(), session.window().phaseNanos(), session.window().damagedPixels());
  }

  private void report(String name, Sample s, Sample e) {
    double sec = (e.nanos() - s.nanos()) / 1e9;
    long frames = e.frames() - s.frames();
    double cpuPct = (e.processCpu() - s.processCpu()) / 1e9 / sec * 100;
    long frameCpu = (e.windowCpu() - s.windowCpu()) + (e.glCpu() - s.glCpu()) - (e.simCpu() - s.simCpu());
    String perFrame = frames == 0 ? "-" : String.format(Locale.ROOT, "%.2f", frameCpu / 1e6 / frames);
    out.printf(Locale.ROOT, "phase=%s fps=%.1f cpu_pct=%.1f frame_cpu_ms=%s frames=%d seconds=%.2f load=%.2f%n",
        name, frames / sec, cpuPct, perFrame, frames, sec,
        ManagementFactory.getOperatingSystemMXBean().getSystemLoadAverage());
    if (System.getenv("ROBOTRUN_BENCH_DETAIL") != null && frames > 0) {
      System.err.printf(Locale.ROOT, "robotrun: %s per frame: window thread %.2f ms, GL threads %.2f ms, simulation %.2f ms%n",
          name, (e.windowCpu() - s.windowCpu()) / 1e6 / frames, (e.glCpu() - s.glCpu()) / 1e6 / frames,
          (e.simCpu() - s.simCpu()) / 1e6 / frames);
      StringBuilder parts = new StringBuilder();
      for (int i = 0; i < e.parts().length; i++) {
        parts.append(String.format(Locale.ROOT, " %s %.2f", org.robotrun.ui.SimulatorWindow.PHASES.get(i),
            (e.parts()[i] - s.parts()[i]) / 1e6 / frames));
      }
      System.err.println("robotrun: " + name + " wall ms per frame:" + parts);
      System.err.printf(Locale.ROOT, "robotrun: %s pixels drawn again per frame: %.0f%n", name,
          (e.damaged() - s.damaged()) / (double) frames);
    }
    out.flush();
  }
}
