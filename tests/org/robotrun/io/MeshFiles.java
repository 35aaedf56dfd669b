package org.robotrun.io;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;

/** Writes small meshes in STL (ASCII, binary), OBJ and COLLADA for importer tests. */
public final class MeshFiles {
  private MeshFiles() {}

  /** An axis-aligned box from {@code lo} to {@code hi}: 12 triangles, counter-clockwise from outside. */
  static double[] box(double[] lo, double[] hi) {
    double[][] c = new double[8][];
    for (int i = 0; i < 8; i++) {
      c[i] = new double[] {(i & 1) == 0 ? lo[0] : hi[0], (i & 2) == 0 ? lo[1] : hi[1], (i & 4) == 0 ? lo[2] : hi[2]};
    }
    int[][] quads = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    double[] out = new double[12 * 9];
    int k = 0;
    for (int[] q : quads) {
      for (int[] t : new int[][] {{q[0], q[1], q[2]}, {q[0], q[2], q[3]}}) {
        for (int v : t) {
          out[k++] = c[v][0];
          out[k++] = c[v][1];
          out[k++] = c[v][2];
        }
      }
    }
    return out;
  }

  /** A cylinder along z from z0 to z1 around (cx, cy), {@code n} sides, closed. */
  static double[] cylinder(double cx, double cy, double r, double z0, double z1, int n) {
    double[] out = new double[n * 4 * 9];
    int k = 0;
    for (int i = 0; i < n; i++) {
      double a0 = 2 * Math.PI * i / n, a1 = 2 * Math.PI * (i + 1) / n;
      double x0 = cx + r * Math.cos(a0), y0 = cy + r * Math.sin(a0);
      double x1 = cx + r * Math.cos(a1), y1 = cy + r * Math.sin(a1);
      double[][] tris = {
          {x0, y0, z0, x1, y1, z0, x1, y1, z1}, {x0, y0, z0, x1, y1, z1, x0, y0, z1},
          {cx, cy, z0, x1, y1, z0, x0, y0, z0}, {cx, cy, z1, x0, y0, z1, x1, y1, z1}};
      for (double[] t : tris) {
        System.arraycopy(t, 0, out, k, 9);
        k += 9;
      }
    }
    return out;
  }

  static double[] concat(double[]... parts) {
    int n = 0;
    for (double[] p : parts) {
      n += p.length;
    }
    double[] out = new double[n];
    int k = 0;
    for (double[] p : parts) {
      System.arraycopy(p, 0, out, k, p.length);
      k += p.length;
    }
    return out;
  }

  static void stlAscii(Path file, double[] t) throws IOException {
    StringBuilder s = new StringBuilder("solid part\n");
    for (int i = 0; i < t.length; i += 9) {
      s.append("  facet normal 0 0 0\n    outer loop\n");
      for (int c = 0; c < 3; c++) {
        s.append(String.format(Locale.ROOT, "      vertex %.9g %.9g %.9g%n", t[i + 3 * c], t[i + 3 * c + 1], t[i + 3 * c + 2]));
      }
      s.append("    endloop\n  endfacet\n");
    }
    s.append("endsolid part\n");
    write(file, s.toString().getBytes(StandardCharsets.US_ASCII));
  }

  static void stlBinary(Path file, double[] t) throws IOException {
    int n = t.length / 9;
    ByteBuffer b = ByteBuffer.allocate(84 + 50 * n).order(ByteOrder.LITTLE_ENDIAN);
    b.position(80);
    b.putInt(n);
    for (int i = 0; i < t.length; i += 9) {
      b.putFloat(0).putFloat(0).putFloat(0);
      for (int c = 0; c < 9; c++) {
        b.putFloat((float) t[i + c]);
      }
      b.putShort((short) 0);
    }
    write(file, b.array());
  }

  static void obj(Path file, double[] t) throws IOException {
    StringBuilder s = new StringBuilder("# test mesh\no part\n");
    for (int i = 0; i < t.length; i += 3) {
      s.append(String.format(Locale.ROOT, "v %.9g %.9g %.9g%n", t[i], t[i + 1], t[i + 2]));
    }
    for (int i = 0; i < t.length / 9; i++) {
      s.append("f ").append(3 * i + 1).append(' ').append(3 * i + 2).append(' ').append(3 * i + 3).append('\n');
    }
    write(file, s.toString().getBytes(StandardCharsets.US_ASCII));
  }

  /** COLLADA 1.4 with one triangle mesh in one node; coordinates in the file's own unit and up axis. */
  static void dae(Path file, double[] t, double unitMeter, String upAxis) throws IOException {
    dae(file, t, unitMeter, upAxis, "");
  }

  /** As above, with {@code nodeXml} (e.g. a {@code <matrix>}) placing the geometry's node. */
  static void dae(Path file, double[] t, double unitMeter, String upAxis, String nodeXml) throws IOException {
    StringBuilder pos = new StringBuilder();
    for (double v : t) {
      pos.append(String.format(Locale.ROOT, "%.9g ", v));
    }
    StringBuilder idx = new StringBuilder();
    for (int i = 0; i < t.length / 3; i++) {
      idx.append(i).append(' ');
    }
    String xml = """
        <?xml version="1.0" encoding="utf-8"?>
        <COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
          <asset>
            <unit name="u" meter="%s"/>
            <up_axis>%s</up_axis>
          </asset>
          <library_geometries>
            <geometry id="g" name="g">
              <mesh>
                <source id="g-pos">
                  <float_array id="g-pos-array" count="%d">%s</float_array>
                  <technique_common>
                    <accessor source="#g-pos-array" count="%d" stride="3">
                      <param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/>
                    </accessor>
                  </technique_common>
                </source>
                <vertices id="g-vtx"><input semantic="POSITION" source="#g-pos"/></vertices>
                <triangles count="%d">
                  <input semantic="VERTEX" source="#g-vtx" offset="0"/>
                  <p>%s</p>
                </triangles>
              </mesh>
            </geometry>
          </library_geometries>
          <library_visual_scenes>
            <visual_scene id="s" name="s">
              <node id="n" name="n">%s<instance_geometry url="#g"/></node>
            </visual_scene>
          </library_visual_scenes>
          <scene><instance_visual_scene url="#s"/></scene>
        </COLLADA>
        """.formatted(Double.toString(unitMeter), upAxis, t.length, pos, t.length / 3, t.length / 9, idx, nodeXml);
    write(file, xml.getBytes(StandardCharsets.UTF_8));
  }

  private static void write(Path file, byte[] bytes) throws IOException {
    Files.createDirectories(file.getParent());
    Files.write(file, bytes);
  }
}
