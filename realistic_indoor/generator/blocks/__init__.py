"""The block layout: a footprint painted as compact blocks of double-loaded and ring corridors."""

from realistic_indoor.generator.blocks.layout import BlockPainter, block_layout
from realistic_indoor.generator.blocks.style import OFFICE_BLOCKS, SCHOOL_BLOCKS, BlockStyle

__all__ = ["OFFICE_BLOCKS", "SCHOOL_BLOCKS", "BlockPainter", "BlockStyle", "block_layout"]
