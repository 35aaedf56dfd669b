package org.robotrun.io;

import java.util.Map;

/**
 * What a workspace would hold if it were saved now: the text of {@code cell.json} and the
 * programs by name. Programs are immutable, so comparing them by identity tells what changed.
 */
public record WorkspaceSnapshot(String cellJson, Map<String, org.robotrun.program.Program> programs) {
  public WorkspaceSnapshot {
    programs = Map.copyOf(programs);
  }
}
