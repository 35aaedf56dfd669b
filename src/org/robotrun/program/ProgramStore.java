package org.robotrun.program;

import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;

/** Where the interpreter finds programs by name (CALL targets and the program to run). */
public interface ProgramStore {

  /** The program called {@code name}, if there is one. */
  Optional<Program> find(String name);

  /** An immutable store of the given programs (a later program with the same name wins). */
  static ProgramStore of(List<Program> programs) {
    Map<String, Program> byName = new HashMap<>();
    for (Program p : programs) {
      byName.put(p.name(), p);
    }
    Map<String, Program> frozen = Map.copyOf(byName);
    return name -> Optional.ofNullable(frozen.get(name));
  }

  /** An immutable store of the given programs. */
  static ProgramStore of(Program... programs) {
    return of(List.of(programs));
  }
}
