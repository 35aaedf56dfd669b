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

  /** Stored entries written by hand: unlike ZipOutputStream it lets a name come twice. */
  static final class DuplicateNameZip implements AutoCloseable {
    private final java.io.ByteArrayOutputStream local = new java.io.ByteArrayOutputStream();
    private final java.io.ByteArrayOutputStream central = new java.io.ByteArrayOutputStream();
    private final java.io.OutputStream out;
    private int count;

    DuplicateNameZip(java.io.OutputStream out) {
      this.out = out;
    }

    void put(String name, byte[] data) {
      byte[] n = name.getBytes(StandardCharsets.UTF_8);
      java.util.zip.CRC32 crc = new java.util.zip.CRC32();
      crc.update(data);
      int offset = local.size();
      var l = java.nio.ByteBuffer.allocate(30 + n.length).order(java.nio.ByteOrder.LITTLE_ENDIAN);
      l.putInt(0x04034b50).putShort((short) 10).putShort((short) 0x800).putShort((short) 0).putInt(0)
          .putInt((int) crc.getValue()).putInt(data.length).putInt(data.length).putShort((short) n.length)
          .putShort((short) 0).put(n);
      local.writeBytes(l.array());
      local.writeBytes(data);
      var c = java.nio.ByteBuffer.allocate(46 + n.length).order(java.nio.ByteOrder.LITTLE_ENDIAN);
      c.putInt(0x02014b50).putShort((short) 10).putShort((short) 10).putShort((short) 0x800).putShort((short) 0)
          .putInt(0).putInt((int) crc.getValue()).putInt(data.length).putInt(data.length).putShort((short) n.length)
          .putShort((short) 0).putShort((short) 0).putShort((short) 0).putShort((short) 0).putInt(0).putInt(offset).put(n);
      central.writeBytes(c.array());
      count++;
    }

    @Override
    public void close() throws java.io.IOException {
      var end = java.nio.ByteBuffer.allocate(22).order(java.nio.ByteOrder.LITTLE_ENDIAN);
      end.putInt(0x06054b50).putShort((short) 0).putShort((short) 0).putShort((short) count).putShort((short) count)
          .putInt(central.size()).putInt(local.size()).putShort((short) 0);
      out.write(local.toByteArray());
      out.write(central.toByteArray());
      out.write(end.array());
    }
  }
}
