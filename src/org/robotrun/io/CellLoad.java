package org.robotrun.io;

import java.util.List;
import java.util.Optional;
import org.robotrun.world.Scenario;

/** The outcome of reading a workspace's {@code cell.json}: the cell and its saved state, or every error found. */
public sealed interface CellLoad {

  /** Read without errors; {@code state} is empty when the file has no {@code "state"} section. */
  record Loaded(Scenario scenario, Optional<SavedState> state) implements CellLoad {}

  /** Not read; at least one error, in file order. */
  record Failed(List<ScenarioError> errors) implements CellLoad {
    public Failed {
      errors = List.copyOf(errors);
      if (errors.isEmpty()) {
        throw new IllegalArgumentException("a failed load needs at least one error");
      }
    }

    /** All errors, one per line. */
    public String message() {
      return String.join("\n", errors.stream().map(ScenarioError::toString).toList());
    }
  }
}
