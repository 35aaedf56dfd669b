package org.robotrun.app;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.Callable;
import org.robotrun.io.Diagnostic;
import org.robotrun.io.LsReadResult;
import org.robotrun.io.LsReader;
import org.robotrun.io.RobotDefinitions;
import org.robotrun.pendant.KeyScript;
import org.robotrun.pendant.Pendant;
import org.robotrun.pendant.RobotControl;
import org.robotrun.pendant.StandInRobotControl;
import org.robotrun.program.Program;
import org.robotrun.sim.DefaultCell;
import org.robotrun.sim.Simulation;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/** {@code robotrun pendant}: drives the teach pendant from a .keys script and prints its LCD. */
@Command(
    name = "pendant",
    mixinStandardHelpOptions = true,
    description = {
      "Run a .keys script on the teach pendant and print the LCD as text at every SHOW.",
      "Script lines: a key (ENTER, F1, SHIFT+FWD, +X/J1, DOWN *3), TYPE text, HOLD key, RELEASE key,",
      "WAIT seconds (simulated), SHOW, and # comments. See docs/pendant.md.",
      "By default the pendant drives the simulation's controller for the default robot (the default cell:",
      "HOME position, UTOOL 1 a 100 mm pointer, UFRAME 1 = WORLD). --controller stand-in uses the stand-in",
      "controller instead: the same program interpreter on a toy gantry arm, no robot kinematics.",
      "Exit codes: 0 script ran (pendant errors show on its prompt line), 2 bad option or malformed script (file:line)."
    })
public final class PendantCommand implements Callable<Integer> {
  @Option(names = "--keys", required = true, paramLabel = "FILE.keys", description = "The key script to run.")
  Path keys;

  @Option(names = "--program", paramLabel = "FILE.LS",
      description = "A TP program (.LS) to load before the script runs; repeat for more. A file with errors is exit 2.")
  List<Path> programs = new java.util.ArrayList<>();

  @Option(names = "--controller", paramLabel = "sim|stand-in", defaultValue = "sim",
      description = "Which controller the pendant drives: sim (default) or stand-in.")
  String controller;

  @Option(names = "--scenario", paramLabel = "FILE",
      description = "Scenario to load first. Not supported by this build yet (no scenario loader): giving one is an error.")
  Path scenario;

  @Spec
  CommandSpec spec;

  @Override
  public Integer call() {
    if (scenario != null) {
      if (!Files.isRegularFile(scenario)) {
        throw new UserError("--scenario: no such file " + scenario);
      }
      throw new UserError("--scenario: this build cannot load scenarios yet (the scenario loader is not merged); "
          + "run without --scenario");
    }
    List<String> lines;
    try {
      lines = Files.readAllLines(keys, StandardCharsets.UTF_8);
    } catch (java.nio.file.NoSuchFileException e) {
      throw new UserError("--keys: no such file " + keys);
    } catch (IOException e) {
      throw new UserError("--keys: cannot read " + keys + " (" + e.getMessage() + ")");
    }
    KeyScript script = switch (KeyScript.parse(keys.toString(), lines)) {
      case KeyScript.Parsed.Ok ok -> ok.script();
      case KeyScript.Parsed.Bad bad -> throw new UserError(bad.error().display());
    };
    RobotControl control = switch (controller) {
      case "sim" -> {
        Simulation sim = DefaultCell.simulation(RobotDefinitions.defaultRobot());
        yield new SimRobotControl(sim, sim.controllers().get(0));
      }
      case "stand-in" -> new StandInRobotControl();
      default -> throw new UserError("--controller: expected sim or stand-in, got '" + controller + "'");
    };
    for (Path file : programs) {
      control.saveProgram(readProgram(file));
    }
    PrintWriter out = spec.commandLine().getOut();
    script.run(new Pendant(control, new LsLineParser()), text -> out.print(text));
    out.flush();
    return Main.EXIT_OK;
  }

  private static Program readProgram(Path file) {
    LsReadResult r;
    try {
      r = LsReader.read(file);
    } catch (java.nio.file.NoSuchFileException e) {
      throw new UserError("--program: no such file " + file);
    } catch (IOException e) {
      throw new UserError("--program: cannot read " + file + " (" + e.getMessage() + ")");
    }
    if (r.hasErrors() || r.program() == null) {
      String first = r.diagnostics().stream().filter(Diagnostic::isError).findFirst().map(Diagnostic::toString)
          .orElse(file + ": not a program");
      throw new UserError("--program: " + first);
    }
    return r.program();
  }
}
