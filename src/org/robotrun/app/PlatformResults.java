package org.robotrun.app;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.SerializationFeature;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Base64;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import org.robotrun.grade.CheckResult;
import org.robotrun.grade.GradeResult;
import org.robotrun.grade.RunOutcome;
import org.robotrun.grade.Task;

/**
 * A graded submission in each course platform's own results format, as the platform publishes
 * it (docs/grading.md names the sources): Gradescope's {@code results.json}, PrairieLearn's
 * external-grader {@code results.json} and GitHub Classroom's autograding runner results. Each
 * also has a failure form (zero points and what the instructor should do) for when a submission
 * could not be graded at all: a broken task, a crash.
 */
final class PlatformResults {
  private static final ObjectMapper JSON = new ObjectMapper().enable(SerializationFeature.INDENT_OUTPUT);
  /** PrairieLearn's limit on the size of results.json. */
  static final int PRAIRIELEARN_MAX_BYTES = 1 << 20;
  /** What the pictures may take of PrairieLearn's limit (the rest is the text). */
  static final int PRAIRIELEARN_PICTURE_BUDGET = 700 * 1024;
  /** The Gradescope leaderboard column. */
  static final String LEADERBOARD_NAME = "Cycle time (s)";

  private PlatformResults() {}

  // ---- Gradescope ----------------------------------------------------------------------------

  /**
   * Gradescope's results.json: {@code score}, {@code execution_time} (whole seconds),
   * {@code output} in Markdown, {@code tests[]} with {@code name}, {@code score},
   * {@code max_score}, {@code status}, {@code output} (plain text) and {@code visibility} (hidden
   * checks get the task's {@code autograder.hiddenVisibility}), {@code stdout_visibility} hidden,
   * and with {@code autograder.leaderboard} the nominal cycle time, ascending.
   *
   * @param students the student names to show ("" when none is known)
   * @param notes lines for the top of the output (e.g. files ignored), may be empty
   */
  static byte[] gradescope(Task task, GradeResult r, String students, List<String> notes, double executionSec)
      throws IOException {
    ObjectNode root = JSON.createObjectNode();
    root.put("score", round(r.score()));
    root.put("execution_time", (long) Math.ceil(Math.max(0, executionSec)));
    StringBuilder md = new StringBuilder();
    md.append("**").append(markdown(task.title())).append("**: ").append(GradeReports.fmt(r.score())).append(" of ")
        .append(GradeReports.fmt(r.maxScore())).append(" points");
    if (!students.isEmpty()) {
      md.append(" (").append(markdown(students)).append(')');
    }
    md.append("\n\n").append(passedLine(r));
    for (String n : notes) {
      md.append("\n\n").append(markdown(n));
    }
    root.put("output", md.toString());
    root.put("output_format", "md");
    root.put("visibility", "visible");
    root.put("stdout_visibility", "hidden");
    ArrayNode tests = root.putArray("tests");
    for (CheckResult c : r.checks()) {
      ObjectNode t = tests.addObject();
      t.put("name", c.name());
      t.put("score", round(c.score()));
      t.put("max_score", round(c.maxScore()));
      t.put("status", c.passed() ? "passed" : "failed");
      t.put("output", c.feedback());
      t.put("output_format", "text");
      t.put("visibility", c.hidden() ? task.autograder().hiddenVisibility() : "visible");
    }
    if (task.autograder().leaderboard()) {
      cycleTime(r).ifPresent(sec -> {
        ObjectNode e = root.putArray("leaderboard").addObject();
        e.put("name", LEADERBOARD_NAME);
        e.put("value", round(sec));
        e.put("order", "asc");
      });
    }
    return JSON.writeValueAsBytes(root);
  }

  /** A results.json for a submission that could not be graded: zero points, the reason, what to do. */
  static byte[] gradescopeFailure(String title, double maxScore, String message) throws IOException {
    ObjectNode root = JSON.createObjectNode();
    root.put("score", 0);
    root.put("output", (title.isEmpty() ? "" : "**" + markdown(title) + "**: ") + "not graded (0 points)\n\n"
        + markdown(message));
    root.put("output_format", "md");
    root.put("visibility", "visible");
    root.put("stdout_visibility", "hidden");
    ObjectNode t = root.putArray("tests").addObject();
    t.put("name", "Autograder");
    t.put("score", 0);
    t.put("max_score", round(maxScore));
    t.put("status", "failed");
    t.put("output", message);
    t.put("output_format", "text");
    t.put("visibility", "visible");
    return JSON.writeValueAsBytes(root);
  }

  /** The first robot's nominal cycle time, when its program reached its END with no alarm. */
  static Optional<Double> cycleTime(GradeResult r) {
    if (r.runs().isEmpty()) {
      return Optional.empty();
    }
    RunOutcome.RobotOutcome first = r.runs().get(0).robots().get(0);
    return first.finished() && first.alarm().isEmpty() ? Optional.of(first.cycleTimeSec()) : Optional.empty();
  }

  // ---- PrairieLearn --------------------------------------------------------------------------

  /** A picture for PrairieLearn: its label and a {@code data:image/png;base64,...} URL. */
  record Picture(String label, String url) {}

  /**
   * PrairieLearn's external-grader results.json: {@code gradable}, {@code score} from 0 to 1,
   * {@code message}, {@code output}, {@code tests[]} with {@code name}, {@code description},
   * {@code points}, {@code max_points}, {@code message}, and {@code images[]} (label, url) as
   * long as the whole file stays within {@link #PRAIRIELEARN_PICTURE_BUDGET}; pictures left out are said so.
   * Hidden checks count, but their feedback is not shown (PrairieLearn shows every test).
   */
  static byte[] prairieLearn(Task task, GradeResult r, List<String> notes, List<Picture> pictures) throws IOException {
    ObjectNode root = JSON.createObjectNode();
    root.put("gradable", true);
    double max = r.maxScore();
    root.put("score", max <= 0 ? 1.0 : Math.max(0, Math.min(1, r.score() / max)));
    StringBuilder message = new StringBuilder(task.title() + ": " + GradeReports.fmt(r.score()) + " of "
        + GradeReports.fmt(max) + " points. " + passedLine(r));
    notes.forEach(n -> message.append('\n').append(n));
    StringBuilder output = new StringBuilder();
    ArrayNode tests = root.putArray("tests");
    for (CheckResult c : r.checks()) {
      ObjectNode t = tests.addObject();
      t.put("name", c.name());
      t.put("description", c.passed() ? "passed" : "failed");
      t.put("points", round(c.score()));
      t.put("max_points", round(c.maxScore()));
      String feedback = c.hidden() ? "(a hidden check: its feedback is not shown)" : c.feedback();
      t.put("message", feedback);
      output.append(c.passed() ? "PASS " : "FAIL ").append(GradeReports.fmt(c.score())).append('/')
          .append(GradeReports.fmt(c.maxScore())).append(' ').append(c.name()).append('\n');
    }
    root.put("output", output.toString());
    ArrayNode images = JSON.createArrayNode();
    int used = 0;
    int left = 0;
    for (Picture p : pictures) {
      int size = p.url().length() + p.label().length() + 40;
      if (used + size > PRAIRIELEARN_PICTURE_BUDGET) {
        left++;
        continue;
      }
      used += size;
      ObjectNode i = images.addObject();
      i.put("label", p.label());
      i.put("url", p.url());
    }
    if (left > 0) {
      message.append('\n').append(left).append(" picture(s) left out to stay within PrairieLearn's 1 MB results limit.");
    }
    root.put("message", message.toString());
    if (!images.isEmpty()) {
      root.set("images", images);
    }
    byte[] bytes = JSON.writeValueAsBytes(root);
    if (bytes.length > PRAIRIELEARN_MAX_BYTES && !images.isEmpty()) {
      return prairieLearn(task, r, notes, List.of());  // the text alone is far below the limit
    }
    return bytes;
  }

  /**
   * A PrairieLearn result for a submission that could not be graded: {@code gradable: false} with
   * {@code format_errors}, so the student loses no attempt and no points.
   */
  static byte[] prairieLearnFailure(String message) throws IOException {
    ObjectNode root = JSON.createObjectNode();
    root.put("gradable", false);
    root.put("score", 0.0);
    root.put("message", message);
    root.putArray("format_errors").add(message);
    return JSON.writeValueAsBytes(root);
  }

  // ---- GitHub Classroom ----------------------------------------------------------------------

  /**
   * GitHub Classroom's autograding results, one runner per check (so the reporter's table and the
   * points it sends to the classroom agree: each runner's score is its one test's), by runner
   * name: {@code {"version": 1, "status": "pass"|"fail", "max_score": P, "tests": [{"name",
   * "status", "score", "message"}]}}. Hidden checks count, with their feedback left out (the
   * workflow's log is the student's).
   */
  static Map<String, byte[]> githubClassroom(Task task, GradeResult r) throws IOException {
    List<String> names = runnerNames(task);
    Map<String, byte[]> out = new LinkedHashMap<>();
    Map<String, CheckResult> byName = new LinkedHashMap<>();
    r.checks().forEach(c -> byName.put(c.name(), c));
    for (int i = 0; i < task.checks().size(); i++) {
      var check = task.checks().get(i);
      CheckResult c = byName.get(check.meta().name());
      boolean passed = c != null && c.passed();
      String message = c == null ? "not graded" : c.hidden() ? "(a hidden check: its feedback is not shown)"
          : c.feedback();
      out.put(names.get(i), runner(check.meta().name(), passed ? "pass" : "fail", check.meta().points(),
          c == null ? 0 : c.score(), message));
    }
    return out;
  }

  /** Every runner "error" with zero points and the reason: the submission could not be graded. */
  static Map<String, byte[]> githubClassroomFailure(Task task, String message) throws IOException {
    List<String> names = runnerNames(task);
    Map<String, byte[]> out = new LinkedHashMap<>();
    for (int i = 0; i < task.checks().size(); i++) {
      var check = task.checks().get(i);
      out.put(names.get(i), runner(check.meta().name(), "error", check.meta().points(), 0, message));
    }
    return out;
  }

  private static byte[] runner(String name, String status, double maxScore, double score, String message)
      throws IOException {
    ObjectNode root = JSON.createObjectNode();
    root.put("version", 1);
    root.put("status", status);
    root.put("max_score", round(maxScore));
    ObjectNode t = root.putArray("tests").addObject();
    t.put("name", name);
    t.put("status", status);
    t.put("score", round(score));
    t.put("message", message);
    return new ObjectMapper().writeValueAsBytes(root);  // one line: it becomes a step output
  }

  /**
   * The runner names of a task's checks, in order: the check's name in lower case letters, digits
   * and '-', unique (GitHub's step outputs and the reporter's {@code NAME_RESULTS} variables are
   * made from them).
   */
  static List<String> runnerNames(Task task) {
    Set<String> used = new LinkedHashSet<>();
    List<String> out = new ArrayList<>();
    for (var c : task.checks()) {
      String base = c.meta().name().toLowerCase(Locale.ROOT).replaceAll("[^a-z0-9]+", "-").replaceAll("^-+|-+$", "");
      if (base.isEmpty() || !Character.isLetter(base.charAt(0))) {
        base = "check-" + base;
      }
      if (base.length() > 40) {
        base = base.substring(0, 40).replaceAll("-+$", "");
      }
      String name = base;
      for (int k = 2; !used.add(name); k++) {
        name = base + "-" + k;
      }
      out.add(name);
    }
    return out;
  }

  /** What a GitHub step output line carries: the runner's JSON, base64 (as the reporter decodes it). */
  static String base64(byte[] json) {
    return Base64.getEncoder().encodeToString(json);
  }

  // ---- shared --------------------------------------------------------------------------------

  private static String passedLine(GradeResult r) {
    long passed = r.checks().stream().filter(CheckResult::passed).count();
    return passed + " of " + r.checks().size() + " checks passed.";
  }

  /** Text from a task or a student shown as Markdown literally: the characters Markdown acts on escaped. */
  static String markdown(String s) {
    StringBuilder b = new StringBuilder(s.length());
    for (int i = 0; i < s.length(); i++) {
      char c = s.charAt(i);
      if ("\\`*_{}[]()<>#+-!|".indexOf(c) >= 0) {
        b.append('\\');
      }
      b.append(c);
    }
    return b.toString();
  }

  static double round(double d) {
    return Math.round(d * 1000) / 1000.0;
  }

  static String utf8(byte[] b) {
    return new String(b, StandardCharsets.UTF_8);
  }
}
