package org.robotrun.app;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.AccessDeniedException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.concurrent.Callable;
import org.robotrun.io.Diagnostic;
import org.robotrun.io.LsProgramSet;
import org.robotrun.io.LsReadResult;
import org.robotrun.io.LsReader;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/** {@code robotrun check FILE.ls...}: reads TP programs and reports every problem, without running them. */
@Command(
    name = "check",
    mixinStandardHelpOptions = true,
    description = {
      "Check FANUC ASCII .LS programs without running them.",
      "Prints one line per problem, 'file:line: message' (warnings say 'warning:'), and nothing for a clean file.",
      "CALL targets are checked against the programs given on the command line, so check a program together "
          + "with the programs it calls (a lone PICK3.LS reports its CALL BEEP as unknown)."
    },
    exitCodeListHeading = "%nExit codes:%n",
    exitCodeList = {
      "0:no errors (warnings may have been printed)",
      "1:errors found in at least one program",
      "2:a file could not be read (missing, a directory, no permission) or bad usage"
    })
public final class CheckCommand implements Callable<Integer> {

  @Spec CommandSpec spec;

  @Parameters(arity = "1..*", paramLabel = "FILE.ls", description = "The programs to check.")
  List<Path> files;

  @Option(names = "--known", split = ",", paramLabel = "NAME",
      description = "Further program names CALL may use (programs already on the controller), comma separated.")
  List<String> known = List.of();

  @Option(names = {"-q", "--quiet"}, description = "Print errors only, not warnings.")
  boolean quiet;

  @Override
  public Integer call() {
    PrintWriter out = spec.commandLine().getOut();
    PrintWriter err = spec.commandLine().getErr();
    boolean unreadable = false;
    List<LsReadResult> results = new ArrayList<>();
    for (Path f : files) {
      try {
        if (Files.isDirectory(f)) {
          throw new IOException("is a directory, expected a .LS file");
        }
        results.add(LsReader.read(f));
      } catch (NoSuchFileException e) {
        err.println(f + ": cannot read: no such file");
        unreadable = true;
      } catch (AccessDeniedException e) {
        err.println(f + ": cannot read: permission denied");
        unreadable = true;
      } catch (IOException e) {
        err.println(f + ": cannot read: " + e.getMessage());
        unreadable = true;
      }
    }

    boolean errors = false;
    for (LsReadResult r : LsProgramSet.crossCheck(results, Set.copyOf(known))) {
      for (Diagnostic d : r.diagnostics()) {
        errors |= d.isError();
        if (d.isError() || !quiet) {
          out.println(d);
        }
      }
    }
    out.flush();
    err.flush();
    if (unreadable) {
      return Main.EXIT_BAD_INPUT;
    }
    return errors ? Main.EXIT_FAILED : Main.EXIT_OK;
  }
}
