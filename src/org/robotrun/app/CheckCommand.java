package org.robotrun.app;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.AccessDeniedException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import java.util.concurrent.Callable;
import java.util.stream.Stream;
import org.robotrun.io.ControllerCompat;
import org.robotrun.io.Diagnostic;
import org.robotrun.io.FileFormatException;
import org.robotrun.io.MacroTables;
import org.robotrun.program.SimulatorEffects;
import org.robotrun.io.LsProgramSet;
import org.robotrun.io.LsReadResult;
import org.robotrun.io.LsReader;
import org.robotrun.io.TerminalText;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/**
 * {@code robotrun check FILE.ls|DIR...}: reads TP programs (every {@code *.LS} of a directory)
 * and reports every problem, without running them.
 */
@Command(
    name = "check",
    mixinStandardHelpOptions = true,
    description = {
      "Check FANUC ASCII .LS programs without running them.",
      "Prints one line per problem, 'file:line: message' (warnings say 'warning:'), and nothing for a clean file.",
      "A directory stands for every *.LS file in it (any case, not in subdirectories), checked in order of name.",
      "CALL targets are checked against all the programs given (files and directories), so check a program together "
          + "with the programs it calls (a lone PICK3.LS reports its CALL BEEP as unknown).",
      "A file whose name (without .LS, any case) is not its /PROG name gets a warning: a controller loads a program "
          + "by its /PROG name.",
      "--format json prints one JSON object instead: {\"diagnostics\":[{\"file\",\"line\",\"column\",\"severity\" "
          + "(error|warning),\"kind\" (syntax|unsupported|reference|range|style),\"message\"}...],\"errors\":N,\"warnings\":N}."
    },
    exitCodeListHeading = "%nExit codes:%n",
    exitCodeList = {
      "0:no errors (warnings may have been printed)",
      "1:errors found in at least one program",
      "2:a file or directory could not be read (missing, no permission, a directory with no .LS file) or bad usage"
    })
public final class CheckCommand implements Callable<Integer> {

  @Spec CommandSpec spec;

  @Parameters(arity = "1..*", paramLabel = "FILE.ls|DIR", description = "The programs to check: .LS files or directories of them.")
  List<Path> files;

  @Option(names = "--known", split = ",", paramLabel = "NAME",
      description = "Further program names CALL may use (programs already on the controller), comma separated.")
  List<String> known = List.of();

  @Option(names = "--macros", paramLabel = "FILE|SCENARIO",
      description = "The cell's macro table: a scenario (.json, its robots' \"macros\") or a text file of "
          + "'MACRO NAME = PROGRAM' lines. Macro lines are then checked against the programs they run; "
          + "without it a macro of several words is reported as not in the macro table.")
  Path macros;

  @Option(names = "--controller", paramLabel = "R-30iA|R-30iB|R-30iB-Plus",
      description = "Also say, line by line, what that controller would refuse (options a standard controller "
          + "lacks, statements of a newer system) or treat differently (comments longer than it keeps), before "
          + "the program goes to the lab's robot (docs/to-the-robot.md).")
  String controller;

  @Option(names = "--io-sizes", split = ",", paramLabel = "KIND=N",
      description = "The lab controller's configured I/O, e.g. DI=64,DO=64,GI=4: each direct I/O index beyond "
          + "it is reported as an error (the controller alarms when the line runs). Kinds: DI, DO, RI, RO, GI, GO, "
          + "AI, AO, SI, SO, F; kinds not named keep RobotRun's defaults.")
  java.util.Map<String, Integer> ioSizes = java.util.Map.of();

  @Option(names = {"-q", "--quiet"}, description = "Print errors only, not warnings.")
  boolean quiet;

  /** Output formats. */
  enum Format { text, json }

  @Option(names = "--format", paramLabel = "text|json", defaultValue = "text",
      description = "Output format: text (file:line: message, the default) or json (for tools and graders).")
  Format format;

  @Override
  public Integer call() {
    PrintWriter out = spec.commandLine().getOut();
    PrintWriter err = spec.commandLine().getErr();
    boolean unreadable = false;
    // files that could not be read at all: on stderr, and in the JSON too (line 0: the whole file)
    List<Diagnostic> fileErrors = new ArrayList<>();
    List<LsReadResult> results = new ArrayList<>();
    for (Path given : files) {
      List<Path> programs;
      try {
        programs = Files.isDirectory(given) ? programsIn(given) : List.of(given);
      } catch (IOException e) {
        err.println(TerminalText.safe(given + ": cannot read: " + reason(e)));
        unreadable = true;
        fileErrors.add(Diagnostic.error(given.toString(), 0, "cannot read: " + reason(e)));
        continue;
      }
      if (programs.isEmpty()) {
        err.println(TerminalText.safe(given + ": no .LS files in this directory"));
        unreadable = true;
        fileErrors.add(Diagnostic.error(given.toString(), 0, "no .LS files in this directory"));
      }
      for (Path f : programs) {
        try {
          results.add(LsReader.readCheckingFileName(f));
        } catch (IOException e) {
          err.println(TerminalText.safe(f + ": cannot read: " + reason(e)));
          unreadable = true;
          fileErrors.add(Diagnostic.error(f.toString(), 0, "cannot read: " + reason(e)));
        }
      }
    }

    ControllerCompat.Model model = null;
    if (controller != null) {
      java.util.Optional<ControllerCompat.Model> m = ControllerCompat.Model.of(controller);
      if (m.isEmpty()) {
        err.println(TerminalText.safe("--controller: unknown controller '" + controller
            + "': expected R-30iA, R-30iB or R-30iB-Plus"));
        return Main.EXIT_BAD_INPUT;
      }
      model = m.get();
    }
    org.robotrun.program.IoRanges labIo = null;
    if (!ioSizes.isEmpty()) {
      try {
        java.util.Map<String, Integer> upper = new java.util.LinkedHashMap<>();
        ioSizes.forEach((k, v) -> upper.put(k.strip().toUpperCase(java.util.Locale.ROOT), v));
        labIo = org.robotrun.program.IoRanges.of(upper);
      } catch (IllegalArgumentException e) {
        err.println(TerminalText.safe("--io-sizes: " + e.getMessage()));
        return Main.EXIT_BAD_INPUT;
      }
    }
    java.util.Map<String, String> table = java.util.Map.of();
    if (macros != null) {
      try {
        table = MacroTables.read(macros);
      } catch (FileFormatException e) {
        err.println(TerminalText.safe("--macros: " + e.getMessage()));
        return Main.EXIT_BAD_INPUT;
      } catch (IOException e) {
        err.println(TerminalText.safe("--macros: " + macros + ": cannot read: " + reason(e)));
        return Main.EXIT_BAD_INPUT;
      }
    }
    boolean errors = false;
    List<Diagnostic> shown = new ArrayList<>(format == Format.json ? fileErrors : List.of());
    for (LsReadResult r : LsProgramSet.crossCheck(results, Set.copyOf(known), table)) {
      List<Diagnostic> all = new ArrayList<>(withSimulatorWarnings(r));
      if (model != null) {
        all.addAll(ControllerCompat.check(r, model));
      }
      if (labIo != null) {
        all.addAll(ControllerCompat.ioBeyond(r, labIo));
      }
      all.sort(Comparator.comparingInt(Diagnostic::line));
      for (Diagnostic d : all) {
        errors |= d.isError();
        if (d.isError() || !quiet) {
          shown.add(d);
        }
      }
    }
    if (format == Format.json) {
      out.println(DiagnosticsJson.write(shown));
    } else {
      shown.forEach(d -> out.println(TerminalText.safe(d.toString())));
    }
    out.flush();
    err.flush();
    if (unreadable) {
      return Main.EXIT_BAD_INPUT;
    }
    return errors ? Main.EXIT_FAILED : Main.EXIT_OK;
  }

  /**
   * The file's diagnostics plus a warning for each line the simulator runs without effect
   * (PAYLOAD, Wjnt: {@link SimulatorEffects}), in line order.
   */
  static List<Diagnostic> withSimulatorWarnings(LsReadResult r) {
    List<Diagnostic> all = new ArrayList<>(r.diagnostics());
    if (r.program() != null) {
      List<org.robotrun.program.Instruction> lines = r.program().lines();
      for (int i = 0; i < lines.size() && i < r.sourceLines().size(); i++) {
        int line = r.sourceLines().get(i);
        SimulatorEffects.noEffect(lines.get(i)).ifPresent(w -> all.add(Diagnostic.warning(r.file(), line, w)));
      }
    }
    all.sort(java.util.Comparator.comparingInt(Diagnostic::line));
    return all;
  }

  /** The regular files of {@code dir} named *.LS (any case), sorted by name. */
  static List<Path> programsIn(Path dir) throws IOException {
    try (Stream<Path> entries = Files.list(dir)) {
      return entries
          .filter(f -> Files.isRegularFile(f) && f.getFileName().toString().toUpperCase(Locale.ROOT).endsWith(".LS"))
          .sorted(Comparator.comparing(f -> f.getFileName().toString()))
          .toList();
    }
  }

  private static String reason(IOException e) {
    return switch (e) {
      case NoSuchFileException x -> "no such file";
      case AccessDeniedException x -> "permission denied";
      default -> e.getMessage() == null ? e.getClass().getSimpleName() : e.getMessage();
    };
  }
}
