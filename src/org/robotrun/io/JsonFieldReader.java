package org.robotrun.io;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import org.robotrun.io.LocatedJson.JArray;
import org.robotrun.io.LocatedJson.JObject;
import org.robotrun.io.LocatedJson.JString;

/**
 * Typed access to a {@link LocatedJson} tree that records every problem as a
 * {@link ScenarioError} (file, line, JSON path, message) instead of stopping at the first: the
 * strict readers of scenario and task files build on it.
 */
public abstract class JsonFieldReader {
  /** Where a reader of one section of a file reports its problems: the reader of the whole file. */
  @FunctionalInterface
  public interface ErrorSink {
    void add(int line, String path, String message);
  }

  protected final String file;
  protected final List<ScenarioError> errors = new ArrayList<>();
  private final ErrorSink sink;

  protected JsonFieldReader(String file) {
    this.file = file;
    this.sink = null;
  }

  /** A reader of a section whose problems go to {@code sink} (the file's reader names the file). */
  protected JsonFieldReader(ErrorSink sink) {
    this.file = "";
    this.sink = java.util.Objects.requireNonNull(sink, "sink");
  }

  protected final void error(int line, String path, String message) {
    if (sink != null) {
      sink.add(line, path, message);
    } else {
      errors.add(new ScenarioError(file, line, path, message));
    }
  }

  /** {@code at.key}, or {@code key} at the top. */
  protected static String join(String at, String key) {
    return at.isEmpty() ? key : at + "." + key;
  }

  /** {@code v} as an object whose keys are all in {@code allowed} (null = any key); null with an error otherwise. */
  protected final JObject object(LocatedJson v, String path, Set<String> allowed) {
    if (!(v instanceof JObject o)) {
      error(v.line(), path, "expected an object, got " + v.describe());
      return null;
    }
    if (allowed != null) {
      for (Map.Entry<String, Integer> k : o.keyLines().entrySet()) {
        if (!allowed.contains(k.getKey())) {
          error(k.getValue(), join(path, k.getKey()), "unknown field (expected one of: "
              + String.join(", ", allowed.stream().sorted().toList()) + ")");
        }
      }
    }
    return o;
  }

  /** The object field {@code key} of {@code o}, or null (with an error when it is required or not an object). */
  protected final JObject member(JObject o, String key, String at, Set<String> allowed, boolean required) {
    LocatedJson v = o.members().get(key);
    if (v == null) {
      if (required) {
        error(o.line(), join(at, key), "missing: expected an object");
      }
      return null;
    }
    return object(v, join(at, key), allowed);
  }

  /** The array field {@code key} of {@code o}, or null (with an error when it is required or not an array). */
  protected final JArray array(JObject o, String key, String at, boolean required) {
    LocatedJson v = o.members().get(key);
    if (v == null) {
      if (required) {
        error(o.line(), join(at, key), "missing: expected an array");
      }
      return null;
    }
    if (!(v instanceof JArray a)) {
      error(v.line(), join(at, key), "expected an array, got " + v.describe());
      return null;
    }
    return a;
  }

  /**
   * The whole-number field {@code key} of {@code o} within {@code min..max}, or {@code fallback}
   * when it is absent or (with an error) anything else.
   */
  protected final int integer(JObject o, String key, String at, int min, int max, int fallback) {
    return integer(o, key, at, (long) min, (long) max, false).map(Long::intValue).orElse(fallback);
  }

  /**
   * The whole-number field {@code key} of {@code o} within {@code min..max} (at most 2^53 in
   * size), or empty when it is absent (an error when required) or (with an error) anything else.
   */
  protected final Optional<Long> integer(JObject o, String key, String at, long min, long max, boolean required) {
    LocatedJson v = o.members().get(key);
    if (v == null) {
      if (required) {
        error(o.line(), join(at, key), "missing: expected a whole number " + min + ".." + max);
      }
      return Optional.empty();
    }
    if (!(v instanceof LocatedJson.JNumber n) || !n.integral() || n.value() < min || n.value() > max) {
      error(v.line(), join(at, key), "expected a whole number " + min + ".." + max + ", got " + v.describe());
      return Optional.empty();
    }
    return Optional.of((long) n.value());
  }

  /**
   * An object key that is a table index ({@code "registers": {"3": ...}}): 1..max, or null with
   * an error naming {@code what} ("register", "user frame").
   */
  protected final Integer keyIndex(String key, int max, int line, String path, String what) {
    try {
      int n = Integer.parseInt(key);
      if (n >= 1 && n <= max) {
        return n;
      }
    } catch (NumberFormatException e) {
      // reported below
    }
    error(line, path, "expected a " + what + " number 1.." + max + " as the key, got \"" + key + "\"");
    return null;
  }

  /** The string field {@code key} of {@code o}, or empty (with an error when it is required or not a string). */
  protected final Optional<String> string(JObject o, String key, String at, boolean required) {
    LocatedJson v = o.members().get(key);
    if (v == null) {
      if (required) {
        error(o.line(), join(at, key), "missing: expected a string");
      }
      return Optional.empty();
    }
    if (!(v instanceof JString s)) {
      error(v.line(), join(at, key), "expected a string, got " + v.describe());
      return Optional.empty();
    }
    return Optional.of(s.value());
  }

  /** The true/false field {@code key} of {@code o}, or empty when it is absent or (with an error) anything else. */
  protected final Optional<Boolean> bool(JObject o, String key, String at) {
    LocatedJson v = o.members().get(key);
    if (v == null) {
      return Optional.empty();
    }
    if (!(v instanceof LocatedJson.JBool b)) {
      error(v.line(), join(at, key), "expected true or false, got " + v.describe());
      return Optional.empty();
    }
    return Optional.of(b.value());
  }

  /**
   * The number field {@code key} of {@code o} within {@code lo..hi}, or {@code fallback} when it
   * is absent (an error when required) or (with an error) anything else.
   */
  protected final double number(JObject o, String key, String at, boolean required, double lo, double hi,
      double fallback) {
    return number(o, key, at, required, lo, hi).orElse(fallback);
  }

  /**
   * The number field {@code key} of {@code o} within {@code lo..hi}, or empty when it is absent
   * (an error when required) or (with an error) anything else.
   */
  protected final Optional<Double> number(JObject o, String key, String at, boolean required, double lo, double hi) {
    LocatedJson v = o.members().get(key);
    if (v == null) {
      if (required) {
        error(o.line(), join(at, key), "missing: expected a number " + plain(lo) + ".." + plain(hi));
      }
      return Optional.empty();
    }
    if (!(v instanceof LocatedJson.JNumber n) || !Double.isFinite(n.value()) || n.value() < lo || n.value() > hi) {
      error(v.line(), join(at, key), "expected a number " + plain(lo) + ".." + plain(hi) + ", got " + v.describe());
      return Optional.empty();
    }
    return Optional.of(n.value());
  }

  /** {@code v} in plain decimal digits (no exponent), as error messages write limits. */
  protected static String plain(double v) {
    return org.robotrun.math.DecimalText.plain(v);
  }
}
