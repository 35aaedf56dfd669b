package org.robotrun.program;

import java.util.List;
import java.util.Objects;

/**
 * How the interpreter reaches the vision system (implemented in {@code sim}; a fake serves the
 * tests): it runs a named vision process, snap and find, and answers what it found, best score
 * first. The vision registers and the per-process list of results not yet fetched live on the
 * program side ({@link VisionRegisters}).
 */
public interface VisionPort {

  /** No vision system: every process name is unknown. */
  VisionPort NONE = new VisionPort() {
    @Override
    public boolean hasProcess(String name) {
      return false;
    }

    @Override
    public Outcome runFind(String name) {
      return new Outcome.Failed(AlarmCode.CVIS_015.code(), "vision process '" + name
          + "' not found (the scenario has no vision section)");
    }
  };

  /** True when a process of this name exists (names are not case-sensitive). */
  boolean hasProcess(String name);

  /** {@code VISION RUN_FIND 'name'}: snaps and finds. */
  Outcome runFind(String name);

  /** What a RUN_FIND gave. */
  sealed interface Outcome {
    /** The parts found, best score first (may be none). */
    record Found(List<VisionResult> results) implements Outcome {
      public Found {
        results = List.copyOf(results);
      }
    }

    /** The process could not run; {@code code} is a CVIS alarm code. */
    record Failed(String code, String message) implements Outcome {
      public Failed {
        Objects.requireNonNull(code, "code");
        Objects.requireNonNull(message, "message");
      }
    }
  }
}
