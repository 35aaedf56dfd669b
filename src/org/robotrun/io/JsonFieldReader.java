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

  /**
   * The whole of {@code text} as an object whose keys are all in {@code allowed}: null (with the
   * error) when it is not JSON or not an object; a key given twice is an error too. A UTF-8 byte
   * order mark in front is ignored.
   */
  protected final JObject topObject(String text, Set<String> allowed) {
    List<LocatedJson.DuplicateKey> duplicates = new ArrayList<>();
    LocatedJson root;
    try {
      root = LocatedJson.parse(text.startsWith("\uFEFF") ? text.substring(1) : text, duplicates);
    } catch (LocatedJson.SyntaxError e) {
      error(e.line(), "", e.getMessage());
      return null;
    }
    for (LocatedJson.DuplicateKey d : duplicates) {
      error(d.line(), d.key(), "field given twice");
    }
    return object(root, "", allowed);
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
    return ranged(o, key, at, required, "a number " + plain(lo) + ".." + plain(hi), x -> x >= lo && x <= hi);
  }

  /**
   * The number field {@code key} of {@code o} above 0 and at most {@code hi} (a size, a distance,
   * a scale), or empty when it is absent (an error when required) or (with an error) anything else.
   */
  protected final Optional<Double> positive(JObject o, String key, String at, boolean required, double hi) {
    return ranged(o, key, at, required, "a number 0.." + plain(hi) + " (more than 0)", x -> x > 0 && x <= hi);
  }

  /**
   * The number field {@code key} of {@code o}, any finite number (a register's value: a register
   * holds any double), or empty when it is absent (an error when required) or (with an error)
   * anything else.
   */
  protected final Optional<Double> finite(JObject o, String key, String at, boolean required) {
    return ranged(o, key, at, required, "a finite number", x -> true);
  }

  private Optional<Double> ranged(JObject o, String key, String at, boolean required, String expected,
      java.util.function.DoublePredicate inRange) {
    LocatedJson v = o.members().get(key);
    if (v == null) {
      if (required) {
        error(o.line(), join(at, key), "missing: expected " + expected);
      }
      return Optional.empty();
    }
    if (!(v instanceof LocatedJson.JNumber n) || !Double.isFinite(n.value()) || !inRange.test(n.value())) {
      error(v.line(), join(at, key), "expected " + expected + ", got " + v.describe());
      return Optional.empty();
    }
    return Optional.of(n.value());
  }

  /**
   * The array field {@code key} of {@code o} holding one of {@code counts} numbers, each within
   * {@code lo..hi}; null when it is absent (an error when required) or, with an error for each
   * bad item, anything else. {@code shape} says what the array holds ({@code "[min, max]"}) in the
   * message about a missing field, another type or another count.
   */
  protected final double[] numbers(JObject o, String key, String at, boolean required, String shape, double lo,
      double hi, int... counts) {
    return items(o, key, at, required, shape, false, lo, hi, counts);
  }

  /** As {@link #numbers}, for whole numbers within {@code lo..hi}. */
  protected final int[] integers(JObject o, String key, String at, boolean required, String shape, int lo, int hi,
      int... counts) {
    double[] d = items(o, key, at, required, shape, true, lo, hi, counts);
    if (d == null) {
      return null;
    }
    int[] out = new int[d.length];
    for (int k = 0; k < d.length; k++) {
      out[k] = (int) d[k];
    }
    return out;
  }

  private double[] items(JObject o, String key, String at, boolean required, String shape, boolean whole, double lo,
      double hi, int... counts) {
    LocatedJson v = o.members().get(key);
    String path = join(at, key);
    if (v == null) {
      if (required) {
        error(o.line(), path, "missing: expected " + shape);
      }
      return null;
    }
    if (!(v instanceof JArray a) || java.util.Arrays.stream(counts).noneMatch(c -> c == a.items().size())) {
      error(v.line(), path, "expected " + shape + ", got "
          + (v instanceof JArray a ? "an array of " + a.items().size() : v.describe()));
      return null;
    }
    double[] out = new double[a.items().size()];
    boolean ok = true;
    for (int k = 0; k < out.length; k++) {
      LocatedJson item = a.items().get(k);
      if (item instanceof LocatedJson.JNumber n && Double.isFinite(n.value()) && n.value() >= lo && n.value() <= hi
          && (!whole || n.integral())) {
        out[k] = n.value();
      } else {
        error(item.line(), path + "[" + k + "]", "expected " + (whole ? "a whole number " : "a number ") + plain(lo)
            + ".." + plain(hi) + ", got " + item.describe());
        ok = false;
      }
    }
    return ok ? out : null;
  }

  /**
   * Checks the top-level {@code "format"} field: present and the whole number {@code expected}
   * (the version of the file kind this RobotRun reads).
   */
  protected final void format(JObject top, int expected) {
    LocatedJson f = top.members().get("format");
    if (f == null) {
      error(top.line(), "format", "missing: expected \"format\": " + expected);
    } else if (!(f instanceof LocatedJson.JNumber n) || !n.integral()) {
      error(f.line(), "format", "expected the integer " + expected + ", got " + f.describe());
    } else if (n.value() != expected) {
      error(f.line(), "format", "unsupported format " + n.text() + ": this RobotRun reads format " + expected);
    }
  }

  /** {@code v} in plain decimal digits (no exponent), as error messages write limits. */
  protected static String plain(double v) {
    return org.robotrun.math.DecimalText.plain(v);
  }
}
