"""XML helpers of the SDF and MJCF writers: safe comments, indented output written whole."""

from __future__ import annotations

import xml.etree.ElementTree as ET

__all__ = ["add_comment", "xml_text"]


def add_comment(parent: ET.Element, text: str) -> None:
    """Append ``<!-- text -->`` to ``parent``; ``--`` (not allowed in a comment) becomes ``- -``."""
    text = " ".join(text.split())
    while "--" in text:
        text = text.replace("--", "- -")
    parent.append(ET.Comment(f" {text} "))


def xml_text(root: ET.Element, head: list[str] | None = None) -> str:
    """``root`` indented by two spaces, after an XML declaration and ``head`` comments."""
    ET.indent(root, space="  ")
    holder = ET.Element("holder")
    for line in head or []:
        add_comment(holder, line)
    comments = "".join(ET.tostring(c, encoding="unicode") + "\n" for c in holder)
    body = ET.tostring(root, encoding="unicode")
    return f'<?xml version="1.0" encoding="UTF-8"?>\n{comments}{body}\n'
