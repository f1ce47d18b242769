//! \file smoothing_record.h
//! \brief Smoothing with a record of what it does to roughness: the roughness
//! profile (and, by default, the Metro-style distance to the input surface) at
//! iteration 0, every K iterations and the last; the studies of the paper's
//! section 6 (Figs. 6-12). Its JSON form is the schema "meshdiff.smoothing/1"
//! (meshdiff/report/json.h).
#pragma once

#include "meshdiff/core/mesh.h"
#include "meshdiff/distance/surface_distance.h"
#include "meshdiff/geometry/sampling.h"
#include "meshdiff/roughness/roughness.h"
#include "meshdiff/studies/smoothing.h"

#include <cstddef>
#include <vector>

namespace meshdiff {

//! What to record while smoothing.
//! The profile `meshdiff smooth` records unless told otherwise: ring levels
//! 1, 5, 10, 20 and the global level (the paper's smoothing plots).
ProfileOptions record_profile_defaults();

struct RecordOptions
{
    //! Record at iteration 0, every `every` iterations and at the last; 0:
    //! only at iteration 0 and the last.
    int every = 0;
    ProfileOptions profile{};  //!< the profile recorded
    //! Also record the surface distance of each recorded state to the input
    //! (surface_distance(input, state, sampling)).
    bool distance = true;
    //! Sampling of that distance; an unset target means 10 x the face count,
    //! as in compare.
    SamplingOptions sampling{};
};

//! The largest RecordOptions::every.
constexpr int kMaxRecordEvery = 1'000'000;

//! The rules of a recording: \p every in 0..kMaxRecordEvery, and a record
//! every K iterations only when it is written somewhere (\p has_output).
//! \throw OptionError("record.every").
void check_recording(int every, bool has_output);

//! The record of smooth_and_record(), one entry per recorded iteration.
struct SmoothingRecord
{
    std::vector<int> iterations;             //!< the recorded iterations, ascending from 0
    std::vector<std::vector<double>> sigma;  //!< per record, sigma per level of RecordOptions::profile
    std::vector<double> sigma_global;        //!< per record (if the profile has the global level)
    std::vector<std::size_t> undefined;      //!< per record: vertices with undefined H
    std::vector<SurfaceDistance> distance;   //!< per record, with RecordOptions::distance
    std::vector<double> flow_time;           //!< explicit flows: flow time at each record, in e^2
    SmoothingReport report;                  //!< what smooth() reported
};

//! Smooths \p mesh in place like smooth() and records the profiles (and
//! distances) of RecordOptions. A callback in \p options is still called.
//! \throw InvalidArgumentError for RecordOptions::every < 0 and as smooth().
//! \throw SolverError, InvalidMeshError as smooth().
SmoothingRecord smooth_and_record(Mesh& mesh, const SmoothingOptions& options, const RecordOptions& record);

}  // namespace meshdiff
