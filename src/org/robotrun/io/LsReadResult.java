package org.robotrun.io;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashSet;
import java.util.List;
import java.util.Locale;
import java.util.Objects;
import java.util.Set;
import java.util.function.Predicate;
import org.robotrun.program.Program;
import org.robotrun.program.ProgramStore;

/**
 * What reading a .LS file gives: the program (as much of it as could be read: a bad /MN line
 * stands as a commented-out line so the numbering of the others holds), every problem found,
 * and for each program line the file line it came from.
 *
 * @param file the file name used in diagnostics
 * @param program the program read
 * @param diagnostics problems in file-line order
 * @param sourceLines {@code sourceLines.get(n - 1)} is the 1-based file line of program line n
 */
public record LsReadResult(String file, Program program, List<Diagnostic> diagnostics, List<Integer> sourceLines) {

  public LsReadResult {
    Objects.requireNonNull(file, "file");
    Objects.requireNonNull(program, "program");
    List<Diagnostic> sorted = new ArrayList<>(diagnostics);
    sorted.sort(Comparator.comparingInt(Diagnostic::line));
    diagnostics = List.copyOf(sorted);
    sourceLines = List.copyOf(sourceLines);
  }

  /**
   * True when the program cannot load: at least one syntax error (a controller refuses such a
   * file too). A missing CALL target or label, an index out of range or an unsupported
   * statement is an error {@code check} reports, but the program loads and that line alarms
   * when it runs, as on the controller.
   */
  public boolean hasErrors() {
    return diagnostics.stream().anyMatch(Diagnostic::blocksLoading);
  }

  /** True when at least one diagnostic is an error of any kind (what {@code check} fails on). */
  public boolean hasAnyError() {
    return diagnostics.stream().anyMatch(Diagnostic::isError);
  }

  /** The file line of program line {@code n} (1-based), for alarms and messages. */
  public int sourceLine(int n) {
    return sourceLines.get(n - 1);
  }

  /**
   * This result plus a diagnostic for every CALL to a program not in {@code knownPrograms}
   * (names compared ignoring case; the program itself always counts as known).
   */
  public LsReadResult withCallTargetsChecked(Set<String> knownPrograms) {
    Set<String> upper = new HashSet<>();
    for (String k : knownPrograms) {
      upper.add(k.toUpperCase(Locale.ROOT));
    }
    return withCallsCheckedBy(name -> upper.contains(name.toUpperCase(Locale.ROOT)));
  }

  /** As {@link #withCallTargetsChecked(Set)}, with the programs of a store (the interpreter's view). */
  public LsReadResult withCallTargetsChecked(ProgramStore store) {
    return withCallsCheckedBy(name -> store.find(name).isPresent());
  }

  /**
   * As {@link #withCallTargetsChecked(Set)}, with the cell's macro table ({@code macroKey} of the
   * macro name → program): a macro the table holds must run a known program.
   */
  public LsReadResult withCallTargetsChecked(Set<String> knownPrograms, java.util.Map<String, String> macros) {
    Set<String> upper = new HashSet<>();
    for (String k : knownPrograms) {
      upper.add(k.toUpperCase(Locale.ROOT));
    }
    List<Diagnostic> all = new ArrayList<>(diagnostics);
    all.addAll(LsProgramChecks.unknownCalls(this, name -> upper.contains(name.toUpperCase(Locale.ROOT)), macros));
    return new LsReadResult(file, program, all, sourceLines);
  }

  private LsReadResult withCallsCheckedBy(Predicate<String> known) {
    List<Diagnostic> all = new ArrayList<>(diagnostics);
    all.addAll(LsProgramChecks.unknownCalls(this, known));
    return new LsReadResult(file, program, all, sourceLines);
  }
}
