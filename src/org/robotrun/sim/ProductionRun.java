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

  /**
   * Steps {@code sim} until the PLC-started work of {@code c} is done. The result has one robot
   * entry, {@code c}'s, with the program its PLC selected (other robots of the cell step along but
   * run nothing of their own).
   */
  public static HeadlessRun.CellResult run(Simulation sim, Controller c, double maxSimSec, Consumer<Simulation> afterTick,
      BooleanSupplier stop, String stopReason) {
    double t0 = sim.timeSec();
    boolean started = false;
    long movingTicks = 0;
    double[] lastQ = c.jointsRad();
    CellStepper stepper = new CellStepper(sim);
    stepper.setAfterTick(afterTick);
    while (true) {
      stepper.tick();
      double t = sim.timeSec();
      double[] q = c.jointsRad();
      if (!java.util.Arrays.equals(q, lastQ)) {
        movingTicks++;
        lastQ = q;
      }
      ExecutionStatus s = c.status();
      Optional<ControllerAlarm> alarm = Optional.empty();
      boolean done = false;
      if (c.hasActiveAlarm()) {
        alarm = Optional.of(c.activeAlarms().get(0));
      } else {
        started |= c.busy();
        done = started && c.uop().plcDone() && s.state() == ExecutionStatus.State.IDLE && !c.busy();
        if (!done && sim.ticks() % STOP_CHECK_TICKS == 0 && stop.getAsBoolean()) {
          alarm = Optional.of(new ControllerAlarm(HeadlessRun.WALL_LIMIT_CODE, stopReason, s.program(), s.line(), t));
        } else if (!done && t - t0 >= maxSimSec) {
          // A start the controller refused is a warning (the PLC waits on): say so, it is why nothing ran.
          String refused = started || c.warnings().isEmpty() ? ""
              : "; the PLC's start was refused: " + c.warnings().get(c.warnings().size() - 1).display();
          alarm = Optional.of(new ControllerAlarm(HeadlessRun.TIME_LIMIT_CODE, String.format(java.util.Locale.ROOT,
              "time limit reached: the PLC-started cell ran %.1f s of simulated time without ending (PLC step %d of %d)",
              maxSimSec, c.uop().plcStep() + 1, c.uop().setup().map(x -> x.plc().size()).orElse(0)) + refused,
              s.program(), s.line(), t));
        }
      }
      if (done || alarm.isPresent()) {
        String program = c.uop().selectedProgram().isEmpty() ? s.program() : c.uop().selectedProgram();
        HeadlessRun.RobotResult rr = new HeadlessRun.RobotResult(c.name(), program,
            done ? HeadlessRun.RobotStatus.FINISHED : HeadlessRun.RobotStatus.ALARM, alarm, t - t0,
            movingTicks * sim.tickSec());
        return new HeadlessRun.CellResult(done ? HeadlessRun.Status.FINISHED : HeadlessRun.Status.ALARM, alarm, t, t - t0,
            sim.ticks(), List.of(rr));
      }
    }
  }
}
