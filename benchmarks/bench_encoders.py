"""Benchmark of the PPO policies' map encoders: weights and learning time per minibatch.

For the observation of ``realistic-indoor train --preset global-map`` (``scan``, ``local_map``,
``velocity``, ``global_map``, ``time_left`` of ``OfficeExplore-v0``), each encoder of
``PPOConfig.map_encoder`` (``nature``: stable-baselines3's ``CombinedExtractor``; ``compact``:
:class:`~realistic_indoor.agents.rl.encoders.MapEncoder`) encodes a minibatch of random
observations, backpropagates and takes an Adam step; the table gives its weights per image key
and the median milliseconds of that over the repeats, on one torch thread (as training runs).
Learning is that per minibatch, ``n_epochs * total_timesteps / batch_size`` times a run.

Usage::

    .venv/bin/python benchmarks/bench_encoders.py               # seconds
    .venv/bin/python benchmarks/bench_encoders.py --batch 256 --repeats 20
"""

from __future__ import annotations

import argparse
import statistics
import time

from bench_envs import machine


def main(argv: list[str] | None = None) -> None:
    """Run the benchmark and print its table."""
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--batch", type=int, default=256, help="minibatch size (the presets' 256)")
    p.add_argument("--repeats", type=int, default=10, help="timed passes per encoder")
    args = p.parse_args(argv)

    import gymnasium as gym
    import torch
    from stable_baselines3.common.torch_layers import CombinedExtractor

    import realistic_indoor.envs  # noqa: F401  (registers the ids)
    from realistic_indoor.agents.rl.config import ppo_preset
    from realistic_indoor.agents.rl.encoders import MapEncoder

    torch.set_num_threads(1)
    keys = ppo_preset("global-map").obs_keys
    env = gym.make("OfficeExplore-v0", extra_observations=("global_map", "time_left"))
    space = gym.spaces.Dict({k: env.observation_space[k] for k in keys})
    generator = torch.Generator().manual_seed(0)
    batch = {k: torch.rand((args.batch, *space[k].shape), generator=generator) for k in keys}
    print(machine())
    print(f"| encoder | weights per image | ms per minibatch of {args.batch} (forward, backward, Adam) |")
    print("|---|---|---|")
    for name, cls in (("nature", CombinedExtractor), ("compact", MapEncoder)):
        encoder = cls(space)
        optimizer = torch.optim.Adam(encoder.parameters())
        weights = {k: sum(w.numel() for w in part.parameters()) for k, part in encoder.extractors.items()}
        times = []
        for _ in range(args.repeats + 1):
            t0 = time.perf_counter()
            encoder(batch).sum().backward()
            optimizer.step()
            optimizer.zero_grad()
            times.append(time.perf_counter() - t0)
        images = ", ".join(f"{k} {n:,}" for k, n in weights.items() if n)
        print(f"| {name} | {images} | {1000 * statistics.median(times[1:]):.0f} |")


if __name__ == "__main__":
    main()
