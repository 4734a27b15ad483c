"""stable-baselines3's PPO trains on OfficeExplore-v0 with the Dict observation (MultiInputPolicy)."""

from __future__ import annotations

import numpy as np
import pytest
from env_helpers import make_env


@pytest.mark.slow
def test_ppo__trains_a_few_thousand_steps_on_office_explore(request):
    import torch
    from stable_baselines3 import PPO

    threads = torch.get_num_threads()
    torch.set_num_threads(1)  # one core, as the environments get; no oversubscription
    request.addfinalizer(lambda: torch.set_num_threads(threads))
    env = make_env("OfficeExplore-v0", max_steps=200)
    model = PPO("MultiInputPolicy", env, n_steps=256, batch_size=64, n_epochs=2, seed=0, device="cpu")
    assert "NatureCNN" in repr(model.policy.features_extractor)  # the local map is read as an image
    model.learn(total_timesteps=2048)
    obs, _ = env.reset(seed=1)
    action, _ = model.predict(obs, deterministic=True)
    assert env.action_space.contains(np.asarray(action, dtype=np.float32))
    assert model.num_timesteps >= 2048
