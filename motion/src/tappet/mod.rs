//! Tappets of a cam, evaluated as CODESYS `SMC_CamRegister` and `SMC_GetTappetValue` do.
