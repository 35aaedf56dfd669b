package org.robotrun.app;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.SerializationFeature;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.nio.charset.StandardCharsets;
import org.robotrun.io.TerminalText;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import org.robotrun.grade.CheckResult;
import org.robotrun.grade.GradeResult;
import org.robotrun.grade.Task;

/** The grading outputs as bytes: Gradescope results.json, the class CSV and the HTML report. */
final class GradeReports {
  private static final ObjectMapper JSON = new ObjectMapper().enable(SerializationFeature.INDENT_OUTPUT);

  private GradeReports() {}

  /**
   * The Gradescope autograder format (score, output, tests[] with name, score, max_score,
   * status, output, visibility); hidden checks get visibility "hidden".
   */
  static byte[] gradescope(Task task, GradeResult r) throws java.io.IOException {
    ObjectNode root = JSON.createObjectNode();
    root.put("score", round(r.score()));
    root.put("output", task.title() + ": " + fmt(r.score()) + " of " + fmt(r.maxScore()) + " points"
        + (r.student().isEmpty() ? "" : " (" + r.student() + ")"));
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
      t.put("visibility", c.hidden() ? "hidden" : "visible");
    }
    return JSON.writeValueAsBytes(root);
  }

  /** One row per submission, one column per check (points given), RFC 4180 quoting. */
  static byte[] summaryCsv(Task task, List<GradeResult> results, List<String> folders) {
    StringBuilder b = new StringBuilder();
    b.append("submission,student,folder,score,max_score");
    task.checks().forEach(c -> b.append(',').append(csv(c.meta().name())));
    b.append("\r\n");
    for (int i = 0; i < results.size(); i++) {
      GradeResult r = results.get(i);
      b.append(csv(r.submission())).append(',').append(csv(r.student())).append(',').append(csv(folders.get(i)))
          .append(',').append(fmt(r.score())).append(',').append(fmt(r.maxScore()));
      Map<String, CheckResult> byName = new java.util.HashMap<>();
      r.checks().forEach(c -> byName.put(c.name(), c));
      for (var c : task.checks()) {
        CheckResult cr = byName.get(c.meta().name());
        b.append(',').append(cr == null ? "" : fmt(cr.score()));
      }
      b.append("\r\n");
    }
    return b.toString().getBytes(StandardCharsets.UTF_8);
  }

  /**
   * A self-contained page: score, each check with points and feedback, the final cell and, for
   * each failed part check, where the part ended (pictures as data URIs; absent pictures say why).
   *
   * @param pictures the overview first, then one per failed part check, in check order (may be empty)
   * @param pictureNote why there are no pictures ("" when there are)
   */
  static byte[] html(Task task, GradeResult r, String overview, Map<String, String> partPictures, String pictureNote) {
    StringBuilder b = new StringBuilder();
    b.append("<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>")
        .append(esc(task.title())).append(" - ").append(esc(r.submission())).append("</title>\n<style>")
        .append("body{font-family:sans-serif;margin:2em;max-width:60em}table{border-collapse:collapse;width:100%}")
        .append("td,th{border:1px solid #ccc;padding:.4em;vertical-align:top;text-align:left}")
        .append(".pass{color:#17692d}.fail{color:#b3261e}pre{white-space:pre-wrap;margin:0;font-family:inherit}")
        .append("img{max-width:100%;border:1px solid #ccc}.hidden{color:#777;font-size:.9em}")
        .append("</style></head><body>\n");
    b.append("<h1>").append(esc(task.title())).append("</h1>\n<p>Submission <b>").append(esc(r.submission()))
        .append("</b>").append(r.student().isEmpty() ? "" : " by <b>" + esc(r.student()) + "</b>")
        .append(": <b>").append(fmt(r.score())).append(" of ").append(fmt(r.maxScore())).append("</b> points.</p>\n");
    b.append("<table><tr><th>check</th><th>result</th><th>points</th><th>what was measured</th></tr>\n");
    for (CheckResult c : r.checks()) {
      b.append("<tr><td>").append(esc(c.name()))
          .append(c.hidden() ? " <span class=\"hidden\">(hidden from students)</span>" : "")
          .append("</td><td class=\"").append(c.passed() ? "pass\">passed" : "fail\">failed").append("</td><td>")
          .append(fmt(c.score())).append(" / ").append(fmt(c.maxScore())).append("</td><td><pre>")
          .append(esc(c.feedback())).append("</pre>");
      String pic = partPictures.get(c.name());
      if (pic != null) {
        b.append("<p>Where it ended:</p><img alt=\"where the part ended\" src=\"").append(pic).append("\">");
      }
      b.append("</td></tr>\n");
    }
    b.append("</table>\n");
    if (!overview.isEmpty()) {
      b.append("<h2>The cell at the end of the nominal run</h2>\n<img alt=\"the cell at the end\" src=\"")
          .append(overview).append("\">\n");
    } else if (!pictureNote.isEmpty()) {
      b.append("<p>").append(esc(pictureNote)).append("</p>\n");
    }
    b.append(String.format(Locale.ROOT, "<p class=\"hidden\">Graded in %.2f s by RobotRun.</p>\n", r.wallSec()));
    b.append("</body></html>\n");
    return b.toString().getBytes(StandardCharsets.UTF_8);
  }

  static String esc(String s) {
    StringBuilder b = new StringBuilder(s.length());
    for (int i = 0; i < s.length(); i++) {
      char c = s.charAt(i);
      switch (c) {
        case '<' -> b.append("&lt;");
        case '>' -> b.append("&gt;");
        case '&' -> b.append("&amp;");
        case '"' -> b.append("&quot;");
        case '\'' -> b.append("&#39;");
        default -> b.append(c);
      }
    }
    return b.toString();
  }

  static String csv(String raw) {
    // Names come from students' files: control characters (NUL, ESC, CR, LF) are escaped as the
    // terminal and the HTML report do, so a row stays one row and no byte can drive a viewer.
    String s = TerminalText.safe(raw.replace("\r", "\\r").replace("\n", "\\n"));
    // A leading = + - @ would be a formula in a spreadsheet; a quote before it keeps it text.
    String v = !s.isEmpty() && "=+-@".indexOf(s.charAt(0)) >= 0 ? "'" + s : s;
    if (v.contains(",") || v.contains("\"") || v.contains("\n") || v.contains("\r")) {
      return "\"" + v.replace("\"", "\"\"") + "\"";
    }
    return v;
  }

  static String fmt(double d) {
    return org.robotrun.math.DecimalText.plain(round(d));
  }

  private static double round(double d) {
    return Math.round(d * 1000) / 1000.0;
  }
}
