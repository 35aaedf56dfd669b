package org.robotrun.app;

import java.io.PrintWriter;
import org.robotrun.io.TerminalText;
import picocli.CommandLine;
import picocli.CommandLine.Command;

/** The {@code robotrun} command: the desktop simulator by default, headless tools as subcommands. */
@Command(
    name = "robotrun",
    mixinStandardHelpOptions = true,
    versionProvider = Main.Version.class,
    description = {
      "RobotRun: a desktop simulator of a 6-axis industrial robot arm for learning to operate and program robots.",
      "With no subcommand it opens the simulator window on the last workspace (or a new default one).",
      "'robotrun --workspace DIR' opens a workspace anywhere. 'robotrun --scenario FILE.json' (or just 'robotrun FILE.json' or 'robotrun FILE.rrcell') starts a new workspace copied from a scenario, as 'robotrun gui' does. 'robotrun PROG.LS' opens with that program added, and 'robotrun HANDIN.zip' opens a hand-in read-only (what a file manager does with these files).",
      ""
    },
    subcommands = {
      GuiCommand.class,
      RenderCommand.class,
      CheckCommand.class,
      PendantCommand.class,
      RunCommand.class,
      GradeCommand.class,
      AutograderCommand.class,
      BenchCommand.class,
      RobotCommand.class,
      RobotsCommand.class,
      CommandLine.HelpCommand.class
    })
public final class Main implements java.util.concurrent.Callable<Integer> {

  /**
   * RobotRun's own extension for a scenario (a cell to start from; the same JSON as a scenario
   * {@code .json}), so that file managers can open it in RobotRun without claiming every
   * {@code .json} file. See docs/install.md.
   */
  public static final String CELL_EXTENSION = ".rrcell";

  /** Exit codes shared by every subcommand. */
  public static final int EXIT_OK = 0;
  public static final int EXIT_FAILED = 1;
  public static final int EXIT_BAD_INPUT = 2;

  @Override
  public Integer call() {
    return new GuiCommand().call();
  }

  public static void main(String[] args) {
    if (args.length == 1 && (args[0].equals("--version") || args[0].equals("-V"))) {
      // Fast path: the same line picocli prints, without building the whole command tree
      // (picocli reflects over every subcommand's annotations first).
      System.out.println(versionLine());
      System.exit(EXIT_OK);
    }
    System.exit(execute(args));
  }

  /** What {@code robotrun --version} prints. */
  static String versionLine() {
    return new Version().getVersion()[0];
  }

  /** Runs the command line and returns the exit code (tests call this). */
  public static int execute(String... args) {
    CommandLine cl = commandLine();
    return cl.execute(withDefaultCommand(args));
  }

  /**
   * The window is the default command, so its options work without naming it:
   * {@code robotrun --scenario F}, {@code robotrun F.json} and {@code robotrun F.rrcell} mean
   * {@code robotrun gui --scenario F}; {@code robotrun F.LS} is {@code gui --program F} and
   * {@code robotrun F.zip} is {@code gui --workspace F}.
   * Anything else (a subcommand, --help, --version) is left as it is.
   */
  static String[] withDefaultCommand(String[] args) {
    if (args.length == 0) {
      return args;
    }
    String first = args[0];
    boolean topLevelOption = first.equals("-h") || first.equals("--help") || first.equals("-V") || first.equals("--version");
    if (first.startsWith("-") && !topLevelOption) {
      return prepend("gui", args);
    }
    // A file first: what a file manager runs for a file associated with RobotRun ('RobotRun
    // FILE'); window options may follow.
    String lower = first.toLowerCase(java.util.Locale.ROOT);
    String option = lower.endsWith(".json") || lower.endsWith(CELL_EXTENSION) ? "--scenario"
        : lower.endsWith(".ls") ? "--program"
        : lower.endsWith(".zip") ? "--workspace"  // a hand-in, read-only
        : null;
    if (option == null) {
      return args;
    }
    String[] out = new String[args.length + 2];
    out[0] = "gui";
    out[1] = option;
    System.arraycopy(args, 0, out, 2, args.length);
    return out;
  }

  private static String[] prepend(String first, String[] rest) {
    String[] out = new String[rest.length + 1];
    out[0] = first;
    System.arraycopy(rest, 0, out, 1, rest.length);
    return out;
  }

  static CommandLine commandLine() {
    CommandLine cl = new CommandLine(new Main());
    // Not picocli's default strategy object: it is one of the old handlers, which remember
    // System.out as it was when the CommandLine was made, and picocli's backwards compatibility
    // then replaces the writer given to setOut with one on that stream whenever System.out has
    // been changed since (a test capturing System.out, an embedding program): the output of every
    // command went to the old stream. A plain strategy keeps setOut's writer (issue 26).
    CommandLine.RunLast runLast = new CommandLine.RunLast();
    cl.setExecutionStrategy(runLast::execute);
    cl.setExecutionExceptionHandler(Main::onExecutionException);
    cl.setParameterExceptionHandler(Main::onParameterException);
    return cl;
  }

  /** Bad command-line input: one line naming the problem, then where to get help. Exit 2. */
  private static int onParameterException(CommandLine.ParameterException e, String[] args) {
    PrintWriter err = e.getCommandLine().getErr();
    err.println(TerminalText.safe("robotrun: " + e.getMessage()));
    err.println("Try '" + e.getCommandLine().getCommandSpec().qualifiedName() + " --help' for more information.");
    err.flush();
    return EXIT_BAD_INPUT;
  }

  /** Anything a command throws becomes one line on stderr, never a stack trace. */
  private static int onExecutionException(Exception e, CommandLine cl, CommandLine.ParseResult pr) {
    PrintWriter err = cl.getErr();
    if (e instanceof UserError ue) {
      err.println(TerminalText.safe("robotrun: " + ue.getMessage()));
      err.flush();
      return ue.exitCode();
    }
    String msg = e.getMessage() == null ? e.getClass().getSimpleName() : e.getMessage();
    err.println(TerminalText.safe("robotrun: internal error: " + msg));
    if (System.getenv("ROBOTRUN_DEBUG") != null) {
      e.printStackTrace(err);
    } else {
      err.println("(set ROBOTRUN_DEBUG=1 to see the details)");
    }
    err.flush();
    return EXIT_FAILED;
  }

  /** Reads the version Maven put into the jar manifest. */
  static final class Version implements CommandLine.IVersionProvider {
    @Override
    public String[] getVersion() {
      String v = Main.class.getPackage().getImplementationVersion();
      return new String[] {"robotrun " + (v == null ? "(development build)" : v)};
    }
  }
}
