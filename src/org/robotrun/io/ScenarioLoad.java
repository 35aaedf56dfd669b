package org.robotrun.io;

import java.util.List;
import org.robotrun.world.Scenario;

/** The outcome of loading a scenario: the whole scenario, or every error found — never half of one. */
public sealed interface ScenarioLoad {

  /** Loaded without errors. */
  record Loaded(Scenario scenario) implements ScenarioLoad {}

  /** Not loaded; at least one error, in file order. */
  record Failed(List<ScenarioError> errors) implements ScenarioLoad {
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
