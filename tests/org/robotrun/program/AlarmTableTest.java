package org.robotrun.program;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.Set;
import java.util.TreeMap;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/**
 * Every alarm the code can raise has a row in the alarm table ({@link AlarmCode}) and in
 * docs/alarms.md. The sources are scanned, not listed by hand: any alarm-code literal
 * ({@code "ABCD-123"}) outside the table, or a reference to a table row that does not exist,
 * fails here.
 */
class AlarmTableTest {
  /** An alarm code as a string literal: a FANUC-style family and number. */
  private static final Pattern CODE_LITERAL = Pattern.compile("\"((?:[A-Z]{4}|RUN)-\\d{3})\\b");
  private static final Pattern TABLE_REF = Pattern.compile("AlarmCode\\.([A-Z]+_\\d{3})\\b");

  @Test
  void everyAlarmCodeInTheSourcesHasARowInTheTable() throws IOException {
    Set<String> table = Arrays.stream(AlarmCode.values()).map(AlarmCode::code).collect(Collectors.toSet());
    Set<String> rowNames = Arrays.stream(AlarmCode.values()).map(Enum::name).collect(Collectors.toSet());
    TreeMap<String, String> missing = new TreeMap<>();
    int refs = 0;
    try (Stream<Path> files = Files.walk(Path.of("src"))) {
      for (Path f : files.filter(p -> p.toString().endsWith(".java")).toList()) {
        String text = Files.readString(f);
        Matcher lit = CODE_LITERAL.matcher(text);
        while (lit.find()) {
          if (!f.endsWith("AlarmCode.java") && !table.contains(lit.group(1))) {
            missing.put(lit.group(1), f.toString());
          }
        }
        Matcher ref = TABLE_REF.matcher(text);
        while (ref.find()) {
          refs++;
          if (!rowNames.contains(ref.group(1))) {
            missing.put(ref.group(1), f.toString());
          }
        }
      }
    }
    assertThat(missing).as("alarm codes raised in src without a row in AlarmCode").isEmpty();
    assertThat(refs).as("the sources raise alarms through the table").isGreaterThan(10);
  }

  @Test
  void everyInterpreterFaultHasARowAndCodesAreUnique() {
    for (AlarmKind k : AlarmKind.values()) {
      assertThat(AlarmCode.of(k.code())).as(k.name()).contains(k.entry());
    }
    assertThat(Arrays.stream(AlarmCode.values()).map(AlarmCode::code).distinct().count())
        .isEqualTo(AlarmCode.values().length);
  }

  @Test
  void ownCodesAreKeptApartFromTheControllers() {
    for (AlarmCode c : AlarmCode.values()) {
      boolean ownFamily = c.code().startsWith("SIMU-") || c.code().startsWith("RUN-");
      assertThat(ownFamily).as(c.code() + " is " + c.source()).isEqualTo(c.source() == AlarmCode.Source.OWN);
      assertThat(c.cause()).isNotBlank();
      assertThat(c.remedy()).isNotBlank();
    }
  }

  @Test
  void docsAlarmsListsEveryRowWithItsSeverity() throws IOException {
    String doc = Files.readString(Path.of("docs/alarms.md"));
    for (AlarmCode c : AlarmCode.values()) {
      assertThat(doc).as(c.code()).contains("| " + c.code() + " | " + c.severity() + " | " + c.text() + " |");
    }
    Matcher m = Pattern.compile("\\| ([A-Z]{3,4}-\\d{3}) \\|").matcher(doc);
    while (m.find()) {
      assertThat(AlarmCode.of(m.group(1))).as("docs/alarms.md row " + m.group(1) + " is in the table").isPresent();
    }
  }
}
