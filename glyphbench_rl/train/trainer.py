"""The built-in trainer: one machine, one policy, read top to bottom.

Each step: for ``groups_per_update`` groups, take the next task of the cycle and play
``group_size`` episodes of it on distinct training seeds with the current policy; compute
group-relative advantages; build training sequences from the exact sampled ids; one AdamW update
over micro-batches whose loss is normalised by the step's total trainable tokens. Every seed, the
task cursor and the sampling stream derive from (config seed, step), so a resumed run continues
exactly where a checkpoint left it.

Run directory: ``config.yaml`` (resolved), ``metrics.jsonl`` (one line per step, ``train/...`` and
``eval/...`` keys), ``rollouts/step_NNNNNN.jsonl`` (trajectories for replay),
``checkpoints/step_NNNNNN/`` (weights, tokenizer, optimizer, state; written under a temporary
name and renamed, so a kill never leaves a half checkpoint), ``eval/step_NNNNNN/`` (held-out jobs).
"""

from __future__ import annotations

import json
import os
import shutil
import statistics
import time
from collections import defaultdict
from pathlib import Path
from typing import Any, Callable

from ..core import resolve_tasks
from ..core.registry import check_engines
from ..core.seeding import generator, training_seeds
from ..rollout.trajectory import Trajectory
from ..rollout.engine import EpisodeSpec, RolloutEngine
from ..agent.parse import EMPTY_TAG, UNKNOWN_NAME
from .advantages import group_advantages
from .config import TrainConfig
from .display import PlainDisplay, log_line
from .policy import HFPolicy, Policy
from .sinks import open_sinks
from .samples import Sample, micro_batches, trajectory_samples

CKPT_PREFIX = "step_"


def write_atomic(path: Path, text: str) -> None:
    tmp = path.with_name(f".{path.name}.tmp")
    tmp.write_text(text, encoding="utf-8")
    os.replace(tmp, path)


class Trainer:
    def __init__(self, config: TrainConfig, out: str | Path, *, resume: bool = False,
                 log: Callable[[str], None] = log_line, policy: Policy | None = None,
                 model=None, tokenizer=None) -> None:
        """``policy`` (default: ``config.model`` loaded as an ``HFPolicy``; ``model`` and
        ``tokenizer`` wrap an already loaded transformers model)."""
        import torch

        self.cfg, self.out, self.log = config, Path(out), log
        self.tasks = resolve_tasks(config.tasks)        # unknown IDs fail before any model loads,
        check_engines(self.tasks)                       # and so do engines whose extra is missing
        self.harness = config.harness_config()
        if not resume and (self.out / "metrics.jsonl").exists():
            raise FileExistsError(f"{self.out} already holds a run; pass --resume to continue it "
                                  f"or choose another --out")
        self.out.mkdir(parents=True, exist_ok=True)
        self.sinks = open_sinks(self.out, config)       # a missing sink package fails here too
        self.display = PlainDisplay(config.steps, log)
        ckpt = latest_checkpoint(self.out) if resume else None
        if policy is None and model is None:
            log(f"loading {ckpt or config.model}")
            policy = HFPolicy.load(str(ckpt) if ckpt else config.model, config.model,
                                   device=config.device, dtype=config.dtype,
                                   gradient_checkpointing=config.gradient_checkpointing)
        else:
            if policy is None:
                policy = HFPolicy(model, tokenizer, config.model,
                                  gradient_checkpointing=config.gradient_checkpointing)
            if ckpt is not None:
                policy.load_weights(ckpt)
        self.policy = policy
        self.optimizer = torch.optim.AdamW(policy.parameters(), lr=config.lr, betas=tuple(config.betas),
                                           weight_decay=config.weight_decay)
        self.step = 0
        if ckpt is not None:
            state = json.loads((ckpt / "state.json").read_text())
            self.step = state["step"]
            if (ckpt / "optimizer.pt").exists():
                self.optimizer.load_state_dict(torch.load(ckpt / "optimizer.pt", weights_only=True))
                log(f"resumed {self.out} from {ckpt.name} (step {self.step})")
            else:
                log(f"resumed {self.out} from {ckpt.name} (step {self.step}) without optimizer "
                    f"state (saved with save_optimizer: false): AdamW starts afresh")
        elif resume:
            log(f"{self.out} has no checkpoint yet: starting over from step 0")
        if resume:
            self._discard_after(self.step)
        write_atomic(self.out / "config.yaml", _yaml(config.to_dict()))
        self._torch = torch

    # -- the loop ---------------------------------------------------------------------------------
    def run(self, display=None) -> None:
        """Train until ``cfg.steps``; ``display`` (train.display) shows progress, default plain lines."""
        self.display = display or PlainDisplay(self.cfg.steps, self.log, start=self.step)
        try:
            while self.step < self.cfg.steps:
                metrics = self.train_step()
                if self.cfg.eval_every and self.step % self.cfg.eval_every == 0:
                    self.display.phase("held-out evaluation")
                    metrics.update(self.evaluate())
                with open(self.out / "metrics.jsonl", "a", encoding="utf-8") as fh:
                    fh.write(json.dumps(metrics) + "\n")
                for sink in self.sinks:
                    sink.log(metrics, self.step)
                if self.step % self.cfg.checkpoint_every == 0 or self.step == self.cfg.steps:
                    self.display.phase("checkpoint")
                    self.save_checkpoint()
                self.display.step_done(metrics)     # after the checkpoint: the step is complete
        finally:
            for sink in self.sinks:
                sink.close()

    def train_step(self) -> dict[str, Any]:
        cfg = self.cfg
        step = self.step + 1
        t0 = time.perf_counter()
        trajs = self.rollouts(step)
        t_roll = time.perf_counter() - t0
        samples, skipped, group_stats = self.samples(trajs)
        self.display.phase(f"update ({sum(s.trainable for s in samples):,} trainable tokens)")
        t1 = time.perf_counter()
        loss_stats = self.update(samples)
        t_train = time.perf_counter() - t1
        self.step = step
        if cfg.save_rollouts:
            self._save_rollouts(step, trajs)
        returns = [t.episode_return for t in trajs]
        per_task: dict[str, list[float]] = defaultdict(list)
        for t in trajs:
            per_task[t.task_id].append(t.episode_return)
        turns = sum(t.length for t in trajs)
        return {
            "step": step,
            "train/return_mean": statistics.fmean(returns),
            "train/return_by_task": {k: statistics.fmean(v) for k, v in per_task.items()},
            "train/forfeit_rate": sum(t.forfeits for t in trajs) / max(1, turns),
            "train/episode_length": turns / len(trajs),
            "train/win_rate": sum(bool(t.won) for t in trajs) / len(trajs),
            "train/format_score": statistics.fmean(format_score(t) for t in trajs),
            "train/completion_tokens": sum(t.completion_tokens for t in trajs),
            "train/trainable_tokens": sum(s.trainable for s in samples),
            "train/sequences": len(samples),
            "train/skipped_tokens": skipped,
            "train/zero_advantage_groups": group_stats,
            **loss_stats,
            "time/rollout_s": t_roll, "time/train_s": t_train,
        }

    def rollouts(self, step: int) -> list[Trajectory]:
        cfg = self.cfg
        specs = []
        overrides = {} if cfg.max_turns is None else {"max_turns": cfg.max_turns}
        for g in range(cfg.groups_per_update):
            k = (step - 1) * cfg.groups_per_update + g      # global group index: the task cursor
            task_id = self.tasks[k % len(self.tasks)]
            for seed in training_seeds(cfg.seed, cfg.group_size, "group", k):
                specs.append(EpisodeSpec(task_id, seed, overrides, group=k, meta={"step": step}))
        backend = self._sampler(seed=int(generator(cfg.seed, "sampling", step).integers(2**62)))
        engine = RolloutEngine(backend, self.harness, max_episodes=cfg.max_episodes_at_once,
                               meta={"model": self.policy.name, "split": "train"})
        done = 0

        def finished(_: Trajectory) -> None:
            nonlocal done
            done += 1
            self.display.phase("rollouts", done, len(specs))

        self.display.phase("rollouts", 0, len(specs))
        return engine.run(specs, on_episode=finished)

    def samples(self, trajs: list[Trajectory]) -> tuple[list[Sample], int, int]:
        groups: dict[int, list[Trajectory]] = defaultdict(list)
        for t in trajs:
            groups[t.group].append(t)
        samples, skipped, flat = [], 0, 0
        for members in groups.values():
            eligible = [self.cfg.include_truncated or not t.truncated for t in members]
            scores = [t.episode_return + self.cfg.format_reward * format_score(t) if self.cfg.format_reward
                      else t.episode_return for t in members]
            adv = group_advantages(scores, eligible,
                                   std_normalize=self.cfg.std_normalize)
            flat += int(not adv.any())
            for t, a, ok in zip(members, adv, eligible):
                if ok and a != 0.0:           # zero advantage: only the KL term would act
                    got, lost = trajectory_samples(t, float(a), self.cfg.seq_len)
                    samples += got
                    skipped += lost
        return samples, skipped, flat

    def _sampler(self, seed: int):
        cfg = self.cfg
        return self.policy.sampler(seed=seed, temperature=cfg.temperature, top_p=cfg.top_p,
                                   max_new_tokens=cfg.max_new_tokens,
                                   batch_size=cfg.max_episodes_at_once)

    def update(self, samples: list[Sample]) -> dict[str, float]:
        from .losses import default_loss, ipo_loss, masked_fraction

        torch, cfg, policy = self._torch, self.cfg, self.policy
        n_tokens = sum(s.trainable for s in samples)
        if n_tokens == 0:
            return {"train/loss": 0.0, "train/grad_norm": 0.0, "train/masked_fraction": 0.0}
        device = policy.device
        policy.train_mode(True)
        self.optimizer.zero_grad(set_to_none=True)
        total, dropped = 0.0, 0.0
        for batch in micro_batches(samples, cfg.micro_batch_tokens):
            width = max(len(s) for s in batch)
            pad = policy.tokenizer.pad_token_id or 0
            ids = torch.tensor([s.ids + [pad] * (width - len(s)) for s in batch], device=device)
            attn = torch.tensor([[1] * len(s) + [0] * (width - len(s)) for s in batch], device=device)
            mask = torch.tensor([s.mask + [0] * (width - len(s)) for s in batch], device=device)
            q = torch.tensor([s.sampling_logprobs + [0.0] * (width - len(s)) for s in batch],
                             device=device, dtype=torch.float32)
            adv = torch.tensor([s.advantage for s in batch], device=device, dtype=torch.float32)
            logp = policy.token_logprobs(ids, attn, chunk=cfg.logprob_chunk, temperature=cfg.temperature)
            if cfg.loss == "ipo":
                loss = ipo_loss(logp, q, adv, mask, threshold=cfg.threshold, kl_coef=cfg.kl_coef,
                                num_tokens=n_tokens)
            else:
                loss = default_loss(logp, q, adv, mask, mask_low=cfg.mask_low, mask_high=cfg.mask_high,
                                    adv_tau=cfg.adv_tau, kl_coef=cfg.kl_coef, num_tokens=n_tokens)
            loss.backward()
            total += float(loss.detach())
            with torch.no_grad():
                dropped += masked_fraction(logp, q, mask, threshold=cfg.threshold) * float(mask.sum())
        norm = torch.nn.utils.clip_grad_norm_(policy.parameters(), cfg.grad_clip)
        self.optimizer.step()
        policy.train_mode(False)
        return {"train/loss": total, "train/grad_norm": float(norm),
                "train/masked_fraction": dropped / n_tokens}

    # -- evaluation ---------------------------------------------------------------------------------
    def evaluate(self) -> dict[str, Any]:
        from ..evaluate.job import EvalConfig, run_job

        cfg = self.cfg
        backend = self._sampler(seed=cfg.seed)
        job = EvalConfig(tasks=self.tasks, backend="hf", episodes=cfg.eval_episodes, model=cfg.model,
                         max_episodes_at_once=cfg.max_episodes_at_once, harness=dict(cfg.harness),
                         context={"train_run": str(self.out), "train_step": self.step})
        res = run_job(job, self.out / "eval" / f"{CKPT_PREFIX}{self.step:06d}", backend=backend,
                      log=None)
        overall = res.summary["overall"]
        return {"eval/return_mean": overall["return_mean"], "eval/return_ci95": overall["return_ci95"],
                "eval/forfeit_rate": overall["forfeit_rate"],
                "eval/return_by_task": {r["task_id"]: r["return_mean"] for r in res.summary["tasks"]}}

    # -- checkpoints --------------------------------------------------------------------------------
    def save_checkpoint(self) -> Path:
        ckpts = self.out / "checkpoints"
        ckpts.mkdir(exist_ok=True)
        final = ckpts / f"{CKPT_PREFIX}{self.step:06d}"
        tmp = ckpts / f".partial-{final.name}"
        shutil.rmtree(tmp, ignore_errors=True)
        self.policy.save(tmp)
        if self.cfg.save_optimizer:
            self._torch.save(self.optimizer.state_dict(), tmp / "optimizer.pt")
        (tmp / "state.json").write_text(json.dumps({"step": self.step}))
        shutil.rmtree(final, ignore_errors=True)
        os.replace(tmp, final)                      # complete, or absent: never half written
        saved = sorted(ckpts.glob(f"{CKPT_PREFIX}*"))
        keep = self.cfg.keep_checkpoints
        for old in saved[:-keep]:
            shutil.rmtree(old, ignore_errors=True)
        for old in saved[-keep:-1]:                 # a resume starts from the latest only
            (old / "optimizer.pt").unlink(missing_ok=True)
        return final

    def _discard_after(self, step: int) -> None:
        """Drop what a stopped run wrote for the steps after ``step`` (they are about to be
        redone, with the weights of that checkpoint): metric lines, rollouts and held-out
        evaluation jobs, so each step's records exist once."""
        path = self.out / "metrics.jsonl"
        if path.exists():
            keep = [line for line in path.read_text(encoding="utf-8").splitlines()
                    if line.strip() and _line_step(line) <= step]
            write_atomic(path, "".join(line + "\n" for line in keep))
        for old in [*(self.out / "rollouts").glob(f"{CKPT_PREFIX}*.jsonl"),
                    *(self.out / "eval").glob(f"{CKPT_PREFIX}*")]:
            if _name_step(old) > step:
                shutil.rmtree(old) if old.is_dir() else old.unlink()

    def _save_rollouts(self, step: int, trajs: list[Trajectory]) -> None:
        d = self.out / "rollouts"
        d.mkdir(exist_ok=True)
        write_atomic(d / f"{CKPT_PREFIX}{step:06d}.jsonl",
                     "".join(json.dumps(t.to_dict()) + "\n" for t in trajs))


def format_score(traj: Trajectory) -> float:
    """Mean over turns of 1 (a valid action), 0.5 (a complete tag naming no action), else 0."""
    if not traj.steps:
        return 0.0
    credit = {None: 1.0, UNKNOWN_NAME: 0.5, EMPTY_TAG: 0.5}
    return statistics.fmean(credit.get(s.forfeit_reason, 0.0) for s in traj.steps)


def latest_checkpoint(out: Path) -> Path | None:
    found = sorted((out / "checkpoints").glob(f"{CKPT_PREFIX}*")) if (out / "checkpoints").exists() else []
    return found[-1] if found else None


def _name_step(path: Path) -> int:
    try:
        return int(path.name.removeprefix(CKPT_PREFIX).split(".")[0])
    except ValueError:
        return -1               # not one of ours: left alone


def _line_step(line: str) -> int:
    try:
        return int(json.loads(line).get("step", 0))
    except (json.JSONDecodeError, AttributeError, TypeError, ValueError):
        return 1 << 62          # a torn last line: dropped with the steps being redone


def _yaml(data: dict) -> str:
    import yaml
    return yaml.safe_dump(data, sort_keys=False)
