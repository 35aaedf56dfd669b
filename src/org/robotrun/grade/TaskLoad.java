package org.robotrun.grade;

import java.util.List;
import org.robotrun.io.ScenarioError;
import org.robotrun.world.Scenario;

/** A task file read: the task and its scenario, or every problem found. */
public sealed interface TaskLoad {
  record Loaded(Task task, Scenario scenario) implements TaskLoad {}

  /** Problems as {@code file:line: path: message}. */
  record Failed(List<ScenarioError> errors) implements TaskLoad {
    public String message() {
      return String.join(System.lineSeparator(), errors.stream().map(ScenarioError::toString).toList());
    }
  }
}
