// The energy-jump rule (scene key energy_jump; docs/stability.md):
//   energy_bound   before the integration: each movable body's T_n and its bound T_max;
//   energy_check   after it: the first body with T_{n+1} > T_max stops the run
//                  ("simulation blew up in step k: kinetic_energy of body ... jumped").
#pragma once

#include "physics/engine/stages/stage.h"

namespace rbw {

class EnergyBoundStage final : public PipelineStep {
public:
    explicit EnergyBoundStage(const std::vector<MassProperties>& mass);
    PipelineStage kind() const override { return PipelineStage::EnergyBound; }
    void run(StepContext& ctx) override;

private:
    std::vector<double> maxInvInertia_;   // per body: largest entry of I0^-1 (diagonal) [1/(kg m^2)]
};

class EnergyCheckStage final : public PipelineStep {
public:
    PipelineStage kind() const override { return PipelineStage::EnergyCheck; }
    void run(StepContext& ctx) override;
};

} // namespace rbw
