package org.robotrun.program;

/** An interpreter with a fake port and fresh registers; runs programs tick by tick. */
final class Rig {
  static final double TICK_SEC = 0.004;

  final Registers regs;
  final FakeMotionPort port;
  final Interpreter interp;

  Rig(InterpreterSettings settings, double motionTimeSec, Program... programs) {
    regs = new Registers(settings.ioRanges());
    port = new FakeMotionPort(motionTimeSec);
    interp = new Interpreter(ProgramStore.of(programs), regs, port, settings);
    interp.select(programs[0].name());
  }

  Rig(Program... programs) {
    this(InterpreterSettings.defaults(), 0.1, programs);
  }

  Outcome tick(double dtSec) {
    port.advance(dtSec);
    return interp.tick(dtSec);
  }

  /** Ticks until the program is not running or waiting any more (at most {@code maxTicks}). */
  Outcome runUntilStopped(double dtSec, int maxTicks) {
    Outcome o = tick(dtSec);
    for (int i = 0; i < maxTicks && !(o instanceof Outcome.Finished || o instanceof Outcome.Paused
        || o instanceof Outcome.Alarmed); i++) {
      o = tick(dtSec);
    }
    return o;
  }

  /** SHIFT+FWD, then run to the end (or a pause/alarm). */
  Outcome run() {
    interp.forward();
    return runUntilStopped(TICK_SEC, 100_000);
  }

  Alarm alarm(Outcome o) {
    if (o instanceof Outcome.Alarmed a) {
      return a.alarm();
    }
    throw new AssertionError("expected an alarm, got " + o);
  }
}
