package org.robotrun.io;

import java.util.Map;

/**
 * What a workspace would hold if it were saved now: the text of {@code cell.json} and the
 * programs by name. Programs are immutable, so comparing them by identity tells what changed.
 */
public record WorkspaceSnapshot(String cellJson, Map<String, org.robotrun.program.Program> programs) {
  public WorkspaceSnapshot {
    // Insertion order is kept: programs are written in that order, so edits land in the order made.
    programs = java.util.Collections.unmodifiableMap(new java.util.LinkedHashMap<>(programs));
  }
}
