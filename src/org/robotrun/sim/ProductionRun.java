package org.robotrun.sim;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.function.BooleanSupplier;
import java.util.function.Consumer;
import org.robotrun.program.Program;
import org.robotrun.world.ProductionSetup;

/**
 * {@code robotrun run} of a scenario whose production setup says the run starts from the PLC:
 * nobody presses SHIFT+FWD; the scenario's PLC sequence drives the UOP inputs and the controller
 * starts what they select. The run ends when the PLC sequence is done and no program or task runs
 * any more (after at least one ran), on an alarm, or at the time limit.
 */
public final class ProductionRun {
  private static final int STOP_CHECK_TICKS = 250;

  private ProductionRun() {}

  /**
   * What the loaded programs make of the setup, before the run: each BG Logic program must exist
   * and be allowed (messages name the JSON path, e.g. {@code production.robot1.backgroundLogic[0]}).
   */
  public static List<String> check(String robot, ProductionSetup.Robot setup, Controller c) {
    List<String> out = new ArrayList<>();
    for (int i = 0; i < setup.backgroundLogic().size(); i++) {
      String name = setup.backgroundLogic().get(i);
      String at = "production." + robot + ".backgroundLogic[" + i + "]";
      Optional<Program> p = c.program(name);
      if (p.isEmpty()) {
        out.add(at + ": no program " + name + " among the loaded files");
      } else {
        BgLogic.refusal(p.get()).ifPresent(why -> out.add(at + ": " + why));
      }
    }
    if (setup.homeProgram().isPresent() && c.program(setup.homeProgram().get()).isEmpty()) {
      out.add("production." + robot + ".homeProgram: no program " + setup.homeProgram().get() + " among the loaded files");
    }
    return out;
  }

  /** Steps {@code sim} until the PLC-started work is done; the result is as {@link HeadlessRun}'s. */
  public static HeadlessRun.Result run(Simulation sim, Controller c, double maxSimSec, Consumer<Simulation> afterTick,
      BooleanSupplier stop, String stopReason) {
    double t0 = sim.timeSec();
    boolean started = false;
    while (true) {
      sim.step();
      afterTick.accept(sim);
      if (c.hasActiveAlarm()) {
        return new HeadlessRun.Result(HeadlessRun.Status.ALARM, Optional.of(c.activeAlarms().get(0)), sim.timeSec(),
            sim.timeSec() - t0, sim.ticks());
      }
      ExecutionStatus s = c.status();
      started |= c.busy();
      if (started && c.uop().plcDone() && s.state() == ExecutionStatus.State.IDLE && !c.busy()) {
        return new HeadlessRun.Result(HeadlessRun.Status.FINISHED, Optional.empty(), sim.timeSec(), sim.timeSec() - t0,
            sim.ticks());
      }
      if (sim.ticks() % STOP_CHECK_TICKS == 0 && stop.getAsBoolean()) {
        ControllerAlarm a = new ControllerAlarm(HeadlessRun.WALL_LIMIT_CODE, stopReason, s.program(), s.line(), sim.timeSec());
        return new HeadlessRun.Result(HeadlessRun.Status.ALARM, Optional.of(a), sim.timeSec(), sim.timeSec() - t0,
            sim.ticks());
      }
      if (sim.timeSec() - t0 >= maxSimSec) {
        ControllerAlarm a = new ControllerAlarm(HeadlessRun.TIME_LIMIT_CODE, String.format(java.util.Locale.ROOT,
            "time limit reached: the PLC-started cell ran %.1f s of simulated time without ending (PLC step %d of %d)",
            maxSimSec, c.uop().plcStep() + 1, c.uop().setup().map(x -> x.plc().size()).orElse(0)),
            s.program(), s.line(), sim.timeSec());
        return new HeadlessRun.Result(HeadlessRun.Status.ALARM, Optional.of(a), sim.timeSec(), sim.timeSec() - t0,
            sim.ticks());
      }
    }
  }
}
