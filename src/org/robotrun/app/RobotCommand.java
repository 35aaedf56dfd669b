package org.robotrun.app;

import picocli.CommandLine.Command;

/** {@code robotrun robot ...}: robot definitions (import a URDF). */
@Command(
    name = "robot",
    mixinStandardHelpOptions = true,
    description = {"Robot definitions: import a URDF as a robot a scenario can name.",
      "'robotrun robot import FILE.urdf --out DIR' turns a URDF into a RobotRun robot a scenario can name (docs/robot-import.md)."},
    subcommands = {RobotImportCommand.class})
public final class RobotCommand implements Runnable {
  @picocli.CommandLine.Spec picocli.CommandLine.Model.CommandSpec spec;

  @Override
  public void run() {
    throw new picocli.CommandLine.ParameterException(spec.commandLine(), "name a robot command: " + String.join(", ", spec.subcommands().keySet()));
  }
}
