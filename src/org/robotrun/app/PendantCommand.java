package org.robotrun.app;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.Callable;
import org.robotrun.pendant.KeyScript;
import org.robotrun.pendant.Pendant;
import org.robotrun.pendant.StandInRobotControl;
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
      "This build runs the pendant on the stand-in controller: the real program interpreter, but a toy",
      "gantry arm (no kinematics of the real robot, no collisions) until the simulation controller is wired.",
      "Exit codes: 0 script ran (pendant errors show on its prompt line), 2 bad option or malformed script (file:line)."
    })
public final class PendantCommand implements Callable<Integer> {
  @Option(names = "--keys", required = true, paramLabel = "FILE.keys", description = "The key script to run.")
  Path keys;

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
    PrintWriter out = spec.commandLine().getOut();
    script.run(new Pendant(new StandInRobotControl()), text -> out.print(text));
    out.flush();
    return Main.EXIT_OK;
  }
}
