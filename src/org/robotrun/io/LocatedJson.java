package org.robotrun.io;

import com.fasterxml.jackson.core.JsonFactory;
import com.fasterxml.jackson.core.JsonParser;
import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.core.JsonToken;
import com.fasterxml.jackson.core.json.JsonReadFeature;
import java.io.IOException;
import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * A JSON tree that remembers the line of every value, so that a loader can report
 * "objects[3].size.x" together with the line it stands on. Parsed with Jackson's streaming
 * parser; {@code NaN} and {@code Infinity} are accepted by the parser so that the loader can
 * reject them with a path rather than a bare syntax error.
 */
public sealed interface LocatedJson {
  /** Line (1-based) where the value starts. */
  int line();

  /** A word for error messages: "an object", "a string", ... */
  String describe();

  record JObject(Map<String, LocatedJson> members, Map<String, Integer> keyLines, int line) implements LocatedJson {
    @Override
    public String describe() {
      return "an object";
    }
  }

  record JArray(List<LocatedJson> items, int line) implements LocatedJson {
    @Override
    public String describe() {
      return "an array";
    }
  }

  record JNumber(double value, boolean integral, String text, int line) implements LocatedJson {
    @Override
    public String describe() {
      return "the number " + text;
    }
  }

  record JString(String value, int line) implements LocatedJson {
    @Override
    public String describe() {
      return "a string";
    }
  }

  record JBool(boolean value, int line) implements LocatedJson {
    @Override
    public String describe() {
      return "a boolean";
    }
  }

  record JNull(int line) implements LocatedJson {
    @Override
    public String describe() {
      return "null";
    }
  }

  /** A syntax error: where and what. */
  final class SyntaxError extends Exception {
    final int line;

    SyntaxError(int line, String message) {
      super(message);
      this.line = line;
    }

    /** 1-based line of the error, 0 when unknown. */
    public int line() {
      return line;
    }
  }

  /** A key that appears twice in one object. */
  record DuplicateKey(String key, int line) {}

  private static JsonFactory factory() {
    return JsonFactory.builder().enable(JsonReadFeature.ALLOW_NON_NUMERIC_NUMBERS).build();
  }

  /** Parses one JSON document; duplicate keys are reported in {@code duplicates} (last one wins). */
  static LocatedJson parse(String text, List<DuplicateKey> duplicates) throws SyntaxError {
    try (JsonParser p = factory().createParser(text)) {
      try {
        JsonToken t = p.nextToken();
        if (t == null) {
          throw new SyntaxError(1, "empty file: expected a JSON object");
        }
        LocatedJson root = value(p, t, duplicates);
        JsonToken extra = p.nextToken();
        if (extra != null) {
          throw new SyntaxError(line(p), "unexpected content after the end of the document");
        }
        return root;
      } catch (JsonProcessingException e) {
        // a limit (nesting) has no location of its own: where the parser stopped
        com.fasterxml.jackson.core.JsonLocation at = e.getLocation() != null ? e.getLocation() : p.currentTokenLocation();
        int line = Math.max(0, at.getLineNr());
        int column = at.getColumnNr();
        throw new SyntaxError(line, "not valid JSON" + (column > 0 ? " at column " + column : "") + ": " + plainReason(e));
      }
    } catch (IOException e) {
      throw new SyntaxError(0, "cannot read: " + e.getMessage());
    }
  }

  private static int line(JsonParser p) {
    return p.currentTokenLocation().getLineNr();
  }

  java.util.regex.Pattern SOURCE =
      java.util.regex.Pattern.compile("at \\[Source: [^\\]]*?; line: (\\d+), column: (\\d+)\\]");

  /**
   * The parser's reason in a user's words: without its internal source markers ("[Source:
   * REDACTED (`StreamReadFeature...` disabled); line: 1, column: 7]" becomes "on line 1, column 7")
   * and without the names of its settings.
   */
  static String plainReason(JsonProcessingException e) {
    if (e instanceof com.fasterxml.jackson.core.exc.StreamConstraintsException) {
      String m = e.getOriginalMessage();
      return m.contains("nesting depth") ? "nested more than " + MAX_DEPTH + " levels deep"
          : m.replaceAll("\\s*\\(from `[^`]*`\\)", "").replaceAll("`[^`]*`", "").strip();
    }
    return SOURCE.matcher(e.getOriginalMessage()).replaceAll("on line $1, column $2");
  }

  /** The parser's limit on nested arrays and objects (Jackson's default). */
  int MAX_DEPTH = com.fasterxml.jackson.core.StreamReadConstraints.DEFAULT_MAX_DEPTH;


  private static LocatedJson value(JsonParser p, JsonToken t, List<DuplicateKey> duplicates) throws IOException {
    int line = line(p);
    return switch (t) {
      case START_OBJECT -> {
        Map<String, LocatedJson> members = new LinkedHashMap<>();
        Map<String, Integer> keyLines = new LinkedHashMap<>();
        for (JsonToken k = p.nextToken(); k != JsonToken.END_OBJECT; k = p.nextToken()) {
          String key = p.currentName();
          int keyLine = line(p);
          LocatedJson v = value(p, p.nextToken(), duplicates);
          if (members.put(key, v) != null) {
            duplicates.add(new DuplicateKey(key, keyLine));
          }
          keyLines.put(key, keyLine);
        }
        yield new JObject(Collections.unmodifiableMap(members), Collections.unmodifiableMap(keyLines), line);
      }
      case START_ARRAY -> {
        List<LocatedJson> items = new ArrayList<>();
        for (JsonToken i = p.nextToken(); i != JsonToken.END_ARRAY; i = p.nextToken()) {
          items.add(value(p, i, duplicates));
        }
        yield new JArray(List.copyOf(items), line);
      }
      case VALUE_NUMBER_INT -> new JNumber(p.getDoubleValue(), true, p.getText(), line);
      case VALUE_NUMBER_FLOAT -> new JNumber(p.getDoubleValue(), false, p.getText(), line);
      case VALUE_STRING -> new JString(p.getText(), line);
      case VALUE_TRUE -> new JBool(true, line);
      case VALUE_FALSE -> new JBool(false, line);
      case VALUE_NULL -> new JNull(line);
      default -> throw new JsonProcessingException("unexpected token " + t, p.currentTokenLocation()) {};
    };
  }
}
