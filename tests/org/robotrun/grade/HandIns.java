package org.robotrun.grade;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.util.HexFormat;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.stream.Stream;
import java.util.zip.ZipEntry;
import java.util.zip.ZipOutputStream;

/** Test helper: hand-in zips as CONTRACTS item 2 describes them, made from a workspace folder. */
final class HandIns {
  private HandIns() {}

  /** Zips {@code workspace} (cell.json, programs/*.LS) with a manifest naming {@code student}. */
  static Path zip(Path workspace, String student, Path zip) throws Exception {
    Map<String, byte[]> files = new LinkedHashMap<>();
    files.put("cell.json", Files.readAllBytes(workspace.resolve("cell.json")));
    try (Stream<Path> s = Files.list(workspace.resolve("programs"))) {
      for (Path p : s.sorted().toList()) {
        files.put("programs/" + p.getFileName(), Files.readAllBytes(p));
      }
    }
    return zip(files, student, zip);
  }

  /** A hand-in of exactly these files, with a correct manifest. */
  static Path zip(Map<String, byte[]> files, String student, Path zip) throws Exception {
    StringBuilder m = new StringBuilder("{\"format\":1,\"student\":\"" + student + "\",\"created\":\"2026-11-23T10:00:00Z\","
        + "\"modified\":\"2026-11-23T10:00:00Z\",\"robotrunVersion\":\"0.1.0-SNAPSHOT\",\"scenario\":\"Pick and place\",\"files\":{");
    String sep = "";
    for (Map.Entry<String, byte[]> e : files.entrySet()) {
      m.append(sep).append('"').append(e.getKey()).append("\":\"").append(sha256(e.getValue())).append('"');
      sep = ",";
    }
    m.append("}}");
    Map<String, byte[]> all = new LinkedHashMap<>();
    all.put("manifest.json", m.toString().getBytes(StandardCharsets.UTF_8));
    all.putAll(files);
    Files.write(zip, rawZip(all));
    return zip;
  }

  /** A plain zip of these entries, in order. */
  static byte[] rawZip(Map<String, byte[]> entries) throws IOException {
    ByteArrayOutputStream out = new ByteArrayOutputStream();
    try (ZipOutputStream z = new ZipOutputStream(out)) {
      for (Map.Entry<String, byte[]> e : entries.entrySet()) {
        z.putNextEntry(new ZipEntry(e.getKey()));
        z.write(e.getValue());
        z.closeEntry();
      }
    }
    return out.toByteArray();
  }

  static String sha256(byte[] b) throws Exception {
    return HexFormat.of().formatHex(MessageDigest.getInstance("SHA-256").digest(b));
  }

  static List<String> failed(GradeResult r) {
    return r.checks().stream().filter(c -> !c.passed()).map(CheckResult::name).toList();
  }

  static CheckResult check(GradeResult r, String name) {
    return r.checks().stream().filter(c -> c.name().equals(name)).findFirst().orElseThrow();
  }
}
