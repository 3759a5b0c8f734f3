#pragma once
// An XML document read with expat into its elements in document order (each with its path from
// the root, attributes and text), for tests that check an XML file's structure field by field.
// The test binary links EXPAT::EXPAT.
#include <expat.h>

#include <map>
#include <string>
#include <vector>

namespace fapcast::test {

struct XmlElement {
  std::string path;  // "root/child/grandchild"
  std::map<std::string, std::string> attributes;
  std::string text;  // the character data directly inside it
};

struct XmlDocument {
  std::vector<XmlElement> elements;
  std::string encoding;  // as declared, "" when not
  std::string error;     // expat's message and line, "" when the document is well formed
};

inline XmlDocument read_xml_elements(const std::string& text) {
  struct State {
    XmlDocument doc;
    std::vector<std::size_t> open;
  } state;
  XML_Parser parser = XML_ParserCreate(nullptr);
  XML_SetUserData(parser, &state);
  XML_SetXmlDeclHandler(parser, [](void* data, const XML_Char*, const XML_Char* encoding, int) {
    static_cast<State*>(data)->doc.encoding = encoding != nullptr ? encoding : "";
  });
  XML_SetElementHandler(
      parser,
      [](void* data, const XML_Char* name, const XML_Char** attributes) {
        auto& s = *static_cast<State*>(data);
        XmlElement e;
        e.path = (s.open.empty() ? std::string() : s.doc.elements[s.open.back()].path + "/") + name;
        for (const XML_Char** a = attributes; *a != nullptr; a += 2) e.attributes[a[0]] = a[1];
        s.open.push_back(s.doc.elements.size());
        s.doc.elements.push_back(std::move(e));
      },
      [](void* data, const XML_Char*) { static_cast<State*>(data)->open.pop_back(); });
  XML_SetCharacterDataHandler(parser, [](void* data, const XML_Char* chars, int n) {
    auto& s = *static_cast<State*>(data);
    if (!s.open.empty()) s.doc.elements[s.open.back()].text.append(chars, static_cast<std::size_t>(n));
  });
  if (XML_Parse(parser, text.data(), static_cast<int>(text.size()), 1) != XML_STATUS_OK)
    state.doc.error = std::string(XML_ErrorString(XML_GetErrorCode(parser))) + " at line " +
                      std::to_string(XML_GetCurrentLineNumber(parser));
  XML_ParserFree(parser);
  return state.doc;
}

}  // namespace fapcast::test
