def test_explored__the_coverage_target_ends_exploration_for_one_coverage_or_many():
    import numpy as np

    from realistic_indoor.envs.config import EnvConfig

    config = EnvConfig(coverage_target=0.8)
    assert config.explored(0.8) and not config.explored(0.79)
    assert config.explored(np.array([0.5, 0.85, 0.8])).tolist() == [False, True, True]
