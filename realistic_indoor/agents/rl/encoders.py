"""Compact encoders of the map images for PPO policies: a small CNN per image, sized for CPU training.

Imported only where a model with ``PPOConfig.map_encoder="compact"`` is trained or loaded (it
needs torch and stable-baselines3).

stable-baselines3's default ``CombinedExtractor`` runs the Atari ``NatureCNN`` (32, 64 and 64
channels) over each image and a 256-wide linear layer over its output: 340 k weights for the
64-pixel ``global_map`` and 334 k for the ``local_map``. :class:`MapEncoder` keeps NatureCNN's
kernels and strides with 16, 32 and 32 channels, averages the last layer down to at most 4 x 4
and feeds a 128-wide layer: 87 k and 84 k weights. A forward pass, backward pass and Adam step
over a minibatch of 256 observations of the ``global-map`` preset took 108 ms against 252 ms on
one thread of a 2-core Intel Xeon under load (``benchmarks/bench_encoders.py``).
"""

from __future__ import annotations

from typing import Any

import torch
from gymnasium import spaces
from stable_baselines3.common.preprocessing import get_flattened_obs_dim, is_image_space
from stable_baselines3.common.torch_layers import BaseFeaturesExtractor
from torch import nn

from realistic_indoor.errors import ConfigError

__all__ = ["MIN_SIDE_PX", "CompactCNN", "MapEncoder"]

MIN_SIDE_PX = 36
"""The smallest image side the three convolutions take (8 with stride 4, 4 with stride 2, 3)."""


class CompactCNN(nn.Module):
    """One image ``(C, H, W)`` uint8 -> ``features_dim`` features.

    Args:
        space: The image's Box space (channels first, values 0-255).
        features_dim: Width of the output.
    """

    def __init__(self, space: spaces.Box, features_dim: int = 128) -> None:
        super().__init__()
        channels, height, width = space.shape
        if min(height, width) < MIN_SIDE_PX:
            raise ConfigError(
                f"the compact map encoder needs images of at least {MIN_SIDE_PX} pixels a side, got "
                f"{height} x {width}; use a larger map (global_map size_px) or map_encoder='nature'"
            )
        self.cnn = nn.Sequential(
            nn.Conv2d(channels, 16, kernel_size=8, stride=4),
            nn.ReLU(),
            nn.Conv2d(16, 32, kernel_size=4, stride=2),
            nn.ReLU(),
            nn.Conv2d(32, 32, kernel_size=3, stride=1),
            nn.ReLU(),
            nn.AdaptiveAvgPool2d(4),
            nn.Flatten(),
        )
        self.linear = nn.Sequential(nn.Linear(32 * 16, features_dim), nn.ReLU())

    def forward(self, image: torch.Tensor) -> torch.Tensor:
        """Features of a batch of images already scaled to [0, 1] (stable-baselines3 does so)."""
        return self.linear(self.cnn(image))


class MapEncoder(BaseFeaturesExtractor):
    """The Dict observation's features: each image key through a :class:`CompactCNN`, the rest flat.

    Args:
        observation_space: The policy's Dict observation space.
        cnn_output_dim: Features per image.
    """

    def __init__(self, observation_space: spaces.Dict, cnn_output_dim: int = 128) -> None:
        super().__init__(observation_space, features_dim=1)
        parts: dict[str, nn.Module] = {}
        width = 0
        for key, space in observation_space.spaces.items():
            if is_image_space(space):
                parts[key] = CompactCNN(space, cnn_output_dim)
                width += cnn_output_dim
            else:
                parts[key] = nn.Flatten()
                width += get_flattened_obs_dim(space)
        self.extractors = nn.ModuleDict(parts)
        self._features_dim = width

    def forward(self, observations: dict[str, Any]) -> torch.Tensor:
        """The concatenated features, keys in the space's order."""
        return torch.cat([part(observations[key]) for key, part in self.extractors.items()], dim=1)
