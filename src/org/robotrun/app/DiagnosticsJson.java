package org.robotrun.app;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.List;
import java.util.Locale;
import org.robotrun.io.Diagnostic;

/** The JSON form of {@code check --format json}: every diagnostic with file, line, column, severity and kind. */
final class DiagnosticsJson {
  private DiagnosticsJson() {}

  private static final ObjectMapper JSON = new ObjectMapper();

  /** {@code {"diagnostics":[...],"errors":N,"warnings":N}} on one line; Jackson escapes control characters. */
  static String write(List<Diagnostic> diagnostics) {
    ObjectNode root = JSON.createObjectNode();
    ArrayNode list = root.putArray("diagnostics");
    int errors = 0;
    for (Diagnostic d : diagnostics) {
      ObjectNode o = list.addObject();
      o.put("file", d.file());
      o.put("line", d.line());
      o.put("column", d.column());
      o.put("severity", d.severity().name().toLowerCase(Locale.ROOT));
      o.put("kind", d.kind().jsonName());
      o.put("message", d.message());
      errors += d.isError() ? 1 : 0;
    }
    root.put("errors", errors);
    root.put("warnings", diagnostics.size() - errors);
    try {
      return JSON.writeValueAsString(root);
    } catch (com.fasterxml.jackson.core.JsonProcessingException e) {
      throw new IllegalStateException("cannot happen: a tree of strings and numbers", e);
    }
  }
}
