package org.robotrun.io;

import java.util.LinkedHashMap;
import java.util.Map;

/**
 * The /ATTR entries a controller writes, in its order, with the values RobotRun writes when a
 * program lacks them (those of a fresh program on the pendant). COMMENT is not here: the model
 * keeps it apart ({@code Program.comment()}); LINE_COUNT is always the real count.
 */
final class LsAttributes {
  private LsAttributes() {}

  static final String COMMENT = "COMMENT";
  static final String LINE_COUNT = "LINE_COUNT";
  static final String TCD = "TCD";

  /** Key → default value, in the order written. COMMENT goes after OWNER. */
  static final Map<String, String> DEFAULTS = defaults();

  private static Map<String, String> defaults() {
    Map<String, String> m = new LinkedHashMap<>();
    m.put("OWNER", "MNEDITOR");
    m.put("PROG_SIZE", "0");
    m.put("CREATE", "DATE 25-01-01  TIME 00:00:00");
    m.put("MODIFIED", "DATE 25-01-01  TIME 00:00:00");
    m.put("FILE_NAME", "");
    m.put("VERSION", "0");
    m.put(LINE_COUNT, "0");
    m.put("MEMORY_SIZE", "0");
    m.put("PROTECT", "READ_WRITE");
    m.put(TCD, "STACK_SIZE = 0, TASK_PRIORITY = 50, TIME_SLICE = 0, BUSY_LAMP_OFF = 0, ABORT_REQUEST = 0, PAUSE_REQUEST = 0");
    m.put("DEFAULT_GROUP", "1,*,*,*,*");
    m.put("CONTROL_CODE", "00000000 00000000");
    return java.util.Collections.unmodifiableMap(m);
  }
}
