"""The block layout shared by offices and schools: compact blocks of double-loaded and ring corridors."""

from realistic_indoor.generator.blocks.layout import block_plan
from realistic_indoor.generator.blocks.style import OFFICE_BLOCKS, SCHOOL_BLOCKS, BlockStyle

__all__ = ["OFFICE_BLOCKS", "SCHOOL_BLOCKS", "BlockStyle", "block_plan"]
