package org.robotrun.app;

import picocli.CommandLine.Command;

/** {@code robotrun bench ...}: benchmarks that print figures. */
@Command(
    name = "bench",
    mixinStandardHelpOptions = true,
    description = "Measure speed: prints one summary line per run.",
    subcommands = {
      BenchRenderCommand.class,
      BenchIkCommand.class,
      BenchParseCommand.class,
      BenchInterpCommand.class,
      BenchCollisionCommand.class,
      BenchBroadPhaseCommand.class,
      BenchScenarioCommand.class,
      BenchSimCommand.class,
      BenchGradeCommand.class,
      BenchCellCommand.class,
      BenchWorkspaceCommand.class,
      BenchVisionCommand.class,
      BenchImportCommand.class,
      BenchWindowCommand.class,
    })
public final class BenchCommand implements Runnable {
  @picocli.CommandLine.Spec picocli.CommandLine.Model.CommandSpec spec;

  @Override
  public void run() {
    throw new picocli.CommandLine.ParameterException(spec.commandLine(), "name a benchmark: " + String.join(", ", spec.subcommands().keySet()));
  }
}
