package org.robotrun.io;

import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.robotrun.program.Program;
import org.robotrun.world.Scenario;

/**
 * What a workspace would hold if it were saved now: the text of {@code cell.json}, the programs
 * by name and, when given, the other named scenarios ({@code scenarios/NAME.json}; empty: the
 * folder is left as it is). Programs and scenarios are immutable, so comparing them by identity
 * tells what changed.
 */
public record WorkspaceSnapshot(String cellJson, Map<String, Program> programs, Optional<List<Scenario>> otherScenarios) {
  public WorkspaceSnapshot {
    // Insertion order is kept: programs are written in that order, so edits land in the order made.
    programs = java.util.Collections.unmodifiableMap(new java.util.LinkedHashMap<>(programs));
    otherScenarios = otherScenarios.map(List::copyOf);
  }

  /** A snapshot that leaves {@code scenarios/} alone. */
  public WorkspaceSnapshot(String cellJson, Map<String, Program> programs) {
    this(cellJson, programs, Optional.empty());
  }

  /** This snapshot with the other scenarios to save. */
  public WorkspaceSnapshot withOtherScenarios(List<Scenario> others) {
    return new WorkspaceSnapshot(cellJson, programs, Optional.of(others));
  }
}
