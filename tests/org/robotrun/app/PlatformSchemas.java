package org.robotrun.app;

import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.JsonNode;
import java.util.Iterator;
import java.util.Set;

/**
 * The course platforms' published results formats, as checks on a JSON document (written from
 * the platforms' own documentation, not from RobotRun's writer):
 *
 * <ul>
 *   <li>Gradescope, "Autograder Specifications" (gradescope-autograders.readthedocs.io/en/latest/specs/):
 *       the top-level and per-test fields, the visibility values, output formats, test status, and
 *       the leaderboard entries (name, value, order asc|desc).
 *   <li>PrairieLearn, "External Grading" (docs.prairielearn.com/externalGrading/): {@code score} in
 *       [0, 1] unless not gradable, {@code gradable}, {@code format_errors} (string or strings),
 *       {@code tests[]} with name, description, points, max_points, message, output, images,
 *       {@code images[]} as {url, label} or a URL string, the file at most 1 MB.
 *   <li>GitHub Classroom's autograding runners (education/autograding-command-grader and
 *       autograding-grading-reporter): {@code {version, status: pass|fail|error, max_score,
 *       tests[]: {name, status, score, message, ...}}}.
 * </ul>
 */
final class PlatformSchemas {
  private static final Set<String> GS_TOP = Set.of("score", "execution_time", "output", "output_format",
      "test_output_format", "test_name_format", "visibility", "stdout_visibility", "extra_data", "tests", "leaderboard");
  private static final Set<String> GS_TEST = Set.of("score", "max_score", "status", "name", "name_format", "number",
      "output", "output_format", "tags", "visibility", "extra_data");
  private static final Set<String> GS_VISIBILITY = Set.of("hidden", "after_due_date", "after_published", "visible");
  private static final Set<String> GS_FORMATS = Set.of("text", "html", "simple_format", "md", "ansi");
  private static final Set<String> PL_TOP = Set.of("gradable", "score", "format_errors", "message", "output", "images",
      "tests", "succeeded", "feedback");
  private static final Set<String> PL_TEST = Set.of("name", "description", "points", "max_points", "message", "output",
      "images");
  private static final Set<String> GH_STATUS = Set.of("pass", "fail", "error");

  private PlatformSchemas() {}

  /** Gradescope's results.json. */
  static void gradescope(JsonNode r) {
    assertThat(r.isObject()).as("results.json is an object").isTrue();
    onlyKeys(r, GS_TOP, "results.json");
    JsonNode tests = r.path("tests");
    boolean everyTestScored = tests.isArray() && !tests.isEmpty();
    for (JsonNode t : tests) {
      everyTestScored &= t.has("score");
    }
    assertThat(r.has("score") || everyTestScored).as("a score at the top or on every test").isTrue();
    if (r.has("score")) {
      assertThat(r.get("score").isNumber()).as("score is a number").isTrue();
    }
    if (r.has("execution_time")) {
      assertThat(r.get("execution_time").isIntegralNumber()).as("execution_time in whole seconds").isTrue();
    }
    textField(r, "output");
    format(r, "output_format");
    format(r, "test_output_format");
    format(r, "test_name_format");
    visibility(r, "visibility");
    visibility(r, "stdout_visibility");
    if (r.has("tests")) {
      assertThat(tests.isArray()).as("tests is an array").isTrue();
      for (JsonNode t : tests) {
        assertThat(t.isObject()).isTrue();
        onlyKeys(t, GS_TEST, "tests[]");
        for (String n : new String[] {"score", "max_score"}) {
          if (t.has(n)) {
            assertThat(t.get(n).isNumber()).as(n + " is a number").isTrue();
          }
        }
        if (t.has("status")) {
          assertThat(t.get("status").asText()).isIn("passed", "failed");
        }
        textField(t, "name");
        textField(t, "output");
        format(t, "output_format");
        format(t, "name_format");
        visibility(t, "visibility");
      }
    }
    if (r.has("leaderboard")) {
      assertThat(r.get("leaderboard").isArray()).isTrue();
      for (JsonNode e : r.get("leaderboard")) {
        onlyKeys(e, Set.of("name", "value", "order"), "leaderboard[]");
        assertThat(e.path("name").isTextual()).isTrue();
        assertThat(e.path("value").isNumber() || e.path("value").isTextual()).isTrue();
        if (e.has("order")) {
          assertThat(e.get("order").asText()).isIn("asc", "desc");
        }
      }
    }
  }

  /** PrairieLearn's external-grader results.json (its bytes, for the size limit). */
  static void prairieLearn(byte[] bytes, JsonNode r) {
    assertThat(bytes.length).as("results.json within PrairieLearn's 1 MB").isLessThanOrEqualTo(1 << 20);
    assertThat(r.isObject()).isTrue();
    onlyKeys(r, PL_TOP, "results.json");
    boolean gradable = !r.has("gradable") || r.get("gradable").asBoolean();
    if (r.has("gradable")) {
      assertThat(r.get("gradable").isBoolean()).isTrue();
    }
    if (gradable) {
      assertThat(r.path("score").isNumber()).as("a gradable result has a score").isTrue();
      assertThat(r.get("score").asDouble()).isBetween(0.0, 1.0);
    }
    if (r.has("format_errors")) {
      JsonNode f = r.get("format_errors");
      assertThat(f.isTextual() || f.isArray()).isTrue();
      f.forEach(e -> assertThat(e.isTextual()).isTrue());
    }
    textField(r, "message");
    textField(r, "output");
    images(r);
    for (JsonNode t : r.path("tests")) {
      onlyKeys(t, PL_TEST, "tests[]");
      textField(t, "name");
      textField(t, "description");
      textField(t, "message");
      textField(t, "output");
      for (String n : new String[] {"points", "max_points"}) {
        if (t.has(n)) {
          assertThat(t.get(n).isNumber()).as(n + " is a number").isTrue();
        }
      }
      images(t);
    }
  }

  /** One GitHub Classroom runner's result, as the reporter reads it. */
  static void githubRunner(JsonNode r) {
    assertThat(r.path("version").asInt()).isEqualTo(1);
    assertThat(r.path("status").asText()).isIn(GH_STATUS);
    assertThat(r.path("max_score").isNumber()).isTrue();
    assertThat(r.path("tests").isArray()).isTrue();
    assertThat(r.path("tests")).isNotEmpty();
    for (JsonNode t : r.get("tests")) {
      assertThat(t.path("name").isTextual()).isTrue();
      assertThat(t.path("status").asText()).isIn(GH_STATUS);
      assertThat(t.path("score").isNumber()).isTrue();
      textField(t, "message");
    }
  }

  private static void images(JsonNode o) {
    if (!o.has("images")) {
      return;
    }
    assertThat(o.get("images").isArray()).isTrue();
    for (JsonNode i : o.get("images")) {
      if (i.isTextual()) {
        continue;
      }
      onlyKeys(i, Set.of("url", "label"), "images[]");
      assertThat(i.path("url").isTextual()).isTrue();
      textField(i, "label");
    }
  }

  private static void onlyKeys(JsonNode o, Set<String> allowed, String where) {
    for (Iterator<String> it = o.fieldNames(); it.hasNext(); ) {
      String k = it.next();
      assertThat(allowed).as(where + " has the field \"" + k + "\", which the format does not define").contains(k);
    }
  }

  private static void textField(JsonNode o, String name) {
    if (o.has(name)) {
      assertThat(o.get(name).isTextual()).as(name + " is a string").isTrue();
    }
  }

  private static void visibility(JsonNode o, String name) {
    if (o.has(name)) {
      assertThat(o.get(name).asText()).as(name).isIn(GS_VISIBILITY);
    }
  }

  private static void format(JsonNode o, String name) {
    if (o.has(name)) {
      assertThat(o.get(name).asText()).as(name).isIn(GS_FORMATS);
    }
  }
}
