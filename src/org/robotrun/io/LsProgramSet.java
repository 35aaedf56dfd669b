package org.robotrun.io;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;

/**
 * Programs read together, as a controller holds them: each CALL must name a program of the set
 * (or one of {@code alsoKnown}), and no two files may define the same program.
 */
public final class LsProgramSet {
  private LsProgramSet() {}

  /**
   * The results with the set-wide diagnostics added: unknown CALL targets, and a program name
   * defined by an earlier file of the list (reported on line 1 of the later file).
   *
   * @param results programs as read, in the order given by the user
   * @param alsoKnown further program names that exist elsewhere (any case)
   */
  public static List<LsReadResult> crossCheck(List<LsReadResult> results, Set<String> alsoKnown) {
    return crossCheck(results, alsoKnown, Map.of());
  }

  /**
   * As {@link #crossCheck(List, Set)}, with the cell's macro table (macro name → program, keyed
   * as {@code InterpreterSettings.macroKey} keys it).
   */
  public static List<LsReadResult> crossCheck(List<LsReadResult> results, Set<String> alsoKnown,
      Map<String, String> macros) {
    Set<String> names = new HashSet<>();
    for (String k : alsoKnown) {
      names.add(k.toUpperCase(Locale.ROOT));
    }
    Map<String, String> fileOf = new HashMap<>();
    List<Diagnostic> duplicates = new ArrayList<>();
    for (LsReadResult r : results) {
      String name = r.program().name().toUpperCase(Locale.ROOT);
      names.add(name);
      String first = fileOf.putIfAbsent(name, r.file());
      if (first != null) {
        duplicates.add(Diagnostic.error(r.file(), 1, "program " + r.program().name() + " is also defined in " + first));
      }
    }
    List<LsReadResult> out = new ArrayList<>(results.size());
    for (LsReadResult r : results) {
      LsReadResult checked = r.withCallTargetsChecked(names, macros);
      List<Diagnostic> all = new ArrayList<>(checked.diagnostics());
      for (Diagnostic d : duplicates) {
        if (d.file().equals(r.file())) {
          all.add(d);
        }
      }
      out.add(new LsReadResult(r.file(), r.program(), all, r.sourceLines()));
    }
    return out;
  }
}
