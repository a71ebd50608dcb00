#pragma once
// The model header that breach/src/core/uses_model.h includes.
