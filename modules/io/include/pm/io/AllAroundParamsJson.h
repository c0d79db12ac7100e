#pragma once
/*!
  \file AllAroundParamsJson.h
  The all-around build's parameters (model::AllAroundParams, a section per stage: AllAroundParams.h)
  as one JSON object: every field under its own name, nested as the structs are.
  What a build was made with, for a record of it and for pm::lab::ModelCache's key (a field left
  out here would let two builds that differ in it share an entry: add each new field).

  \code
    pm::model::AllAroundParams p;
    p.viewpoints.count = 120;
    const std::string json = pm::io::allAroundParamsToJson(p); // {"backdrop_hue_deg":-1.0, ..., "viewpoints":{..., "count":120, ...}}
  \endcode
*/
#include <string>

#include "pm/model/AllAroundModelBuilder.h"

namespace pm::io {

//! \e p as a JSON object (keys sorted; doubles to the last bit).
std::string allAroundParamsToJson(const model::AllAroundParams &p);

} // namespace pm::io
