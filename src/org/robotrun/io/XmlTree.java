package org.robotrun.io;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import javax.xml.XMLConstants;
import javax.xml.parsers.ParserConfigurationException;
import javax.xml.parsers.SAXParser;
import javax.xml.parsers.SAXParserFactory;
import org.xml.sax.Attributes;
import org.xml.sax.Locator;
import org.xml.sax.SAXException;
import org.xml.sax.SAXParseException;
import org.xml.sax.helpers.DefaultHandler;

/**
 * A small XML element tree that remembers each element's line, for file formats whose errors
 * must name a line (URDF, ROS package.xml). No DTDs or external entities are read.
 */
final class XmlTree {
  private XmlTree() {}

  /** One element: its name as written (prefix included), attributes, line, children and text. */
  record Element(String name, Map<String, String> attributes, int line, List<Element> children, String text) {
    Optional<String> attribute(String key) {
      return Optional.ofNullable(attributes.get(key));
    }

    List<Element> children(String childName) {
      return children.stream().filter(c -> c.name.equals(childName)).toList();
    }

    Optional<Element> child(String childName) {
      return children.stream().filter(c -> c.name.equals(childName)).findFirst();
    }
  }

  /** Parses {@code bytes}; {@code source} names the file in errors. */
  static Element parse(String source, byte[] bytes) {
    try {
      SAXParserFactory f = SAXParserFactory.newInstance();
      f.setNamespaceAware(false);
      f.setFeature("http://apache.org/xml/features/disallow-doctype-decl", true);
      f.setFeature(XMLConstants.FEATURE_SECURE_PROCESSING, true);
      SAXParser p = f.newSAXParser();
      Handler h = new Handler();
      p.parse(new ByteArrayInputStream(bytes), h);
      return h.root;
    } catch (SAXParseException e) {
      throw new FileFormatException(source, Math.max(0, e.getLineNumber()), "not well-formed XML: " + e.getMessage());
    } catch (SAXException | ParserConfigurationException | IOException e) {
      throw new FileFormatException(source, 0, "cannot read XML: " + e.getMessage());
    }
  }

  private static final class Handler extends DefaultHandler {
    private Locator locator;
    private final Deque<Builder> open = new ArrayDeque<>();
    Element root;

    private record Builder(String name, Map<String, String> attributes, int line, List<Element> children, StringBuilder text) {}

    @Override
    public void setDocumentLocator(Locator l) {
      locator = l;
    }

    @Override
    public void startElement(String uri, String localName, String qName, Attributes atts) {
      Map<String, String> a = new LinkedHashMap<>();
      for (int i = 0; i < atts.getLength(); i++) {
        a.put(atts.getQName(i), atts.getValue(i));
      }
      open.push(new Builder(qName, a, locator == null ? 0 : locator.getLineNumber(), new ArrayList<>(), new StringBuilder()));
    }

    @Override
    public void characters(char[] ch, int start, int length) {
      if (!open.isEmpty()) {
        open.peek().text.append(ch, start, length);
      }
    }

    @Override
    public void endElement(String uri, String localName, String qName) {
      Builder b = open.pop();
      Element e = new Element(b.name, Map.copyOf(b.attributes), b.line, List.copyOf(b.children), b.text.toString().strip());
      if (open.isEmpty()) {
        root = e;
      } else {
        open.peek().children.add(e);
      }
    }
  }
}
