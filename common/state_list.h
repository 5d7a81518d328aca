/* state_list.h: every Direct3D 9 effect state, as an X-macro list.
 *   X(ID, "Name as effect files spell it", scope, kind, value table, max index)
 * states.h turns it into the hfx_state_id enum, states.c into the lookup table. The ids are
 * stored in .hfxo files: append new states at the end, never reorder. Scope and kind are the
 * suffixes of HFX_SS_* and HFX_SV_*; the value table is a name states.c defines (or NONE).
 * Order and names follow d3dx9's effect state table (render states by D3DRENDERSTATETYPE,
 * then texture-stage states, fixed function, shaders, constants, Texture, sampler states). */
#ifndef HFX_COMMON_STATE_LIST_H
#define HFX_COMMON_STATE_LIST_H

#define HFX_STATE_LIST(X) \
    X(ZENABLE, "ZEnable", RENDER, ENUM, zenable, 0) \
    X(FILLMODE, "FillMode", RENDER, ENUM, fill, 0) \
    X(SHADEMODE, "ShadeMode", RENDER, ENUM, shade, 0) \
    X(ZWRITEENABLE, "ZWriteEnable", RENDER, BOOL, NONE, 0) \
    X(ALPHATESTENABLE, "AlphaTestEnable", RENDER, BOOL, NONE, 0) \
    X(LASTPIXEL, "LastPixel", RENDER, BOOL, NONE, 0) \
    X(SRCBLEND, "SrcBlend", RENDER, ENUM, blend, 0) \
    X(DESTBLEND, "DestBlend", RENDER, ENUM, blend, 0) \
    X(CULLMODE, "CullMode", RENDER, ENUM, cull, 0) \
    X(ZFUNC, "ZFunc", RENDER, ENUM, cmp, 0) \
    X(ALPHAREF, "AlphaRef", RENDER, INT, NONE, 0) \
    X(ALPHAFUNC, "AlphaFunc", RENDER, ENUM, cmp, 0) \
    X(DITHERENABLE, "DitherEnable", RENDER, BOOL, NONE, 0) \
    X(ALPHABLENDENABLE, "AlphaBlendEnable", RENDER, BOOL, NONE, 0) \
    X(FOGENABLE, "FogEnable", RENDER, BOOL, NONE, 0) \
    X(SPECULARENABLE, "SpecularEnable", RENDER, BOOL, NONE, 0) \
    X(FOGCOLOR, "FogColor", RENDER, COLOR, NONE, 0) \
    X(FOGTABLEMODE, "FogTableMode", RENDER, ENUM, fog, 0) \
    X(FOGSTART, "FogStart", RENDER, FLOAT, NONE, 0) \
    X(FOGEND, "FogEnd", RENDER, FLOAT, NONE, 0) \
    X(FOGDENSITY, "FogDensity", RENDER, FLOAT, NONE, 0) \
    X(RANGEFOGENABLE, "RangeFogEnable", RENDER, BOOL, NONE, 0) \
    X(STENCILENABLE, "StencilEnable", RENDER, BOOL, NONE, 0) \
    X(STENCILFAIL, "StencilFail", RENDER, ENUM, stencilop, 0) \
    X(STENCILZFAIL, "StencilZFail", RENDER, ENUM, stencilop, 0) \
    X(STENCILPASS, "StencilPass", RENDER, ENUM, stencilop, 0) \
    X(STENCILFUNC, "StencilFunc", RENDER, ENUM, cmp, 0) \
    X(STENCILREF, "StencilRef", RENDER, INT, NONE, 0) \
    X(STENCILMASK, "StencilMask", RENDER, INT, NONE, 0) \
    X(STENCILWRITEMASK, "StencilWriteMask", RENDER, INT, NONE, 0) \
    X(TEXTUREFACTOR, "TextureFactor", RENDER, COLOR, NONE, 0) \
    X(WRAP0, "Wrap0", RENDER, FLAGS, wrap, 0) \
    X(WRAP1, "Wrap1", RENDER, FLAGS, wrap, 0) \
    X(WRAP2, "Wrap2", RENDER, FLAGS, wrap, 0) \
    X(WRAP3, "Wrap3", RENDER, FLAGS, wrap, 0) \
    X(WRAP4, "Wrap4", RENDER, FLAGS, wrap, 0) \
    X(WRAP5, "Wrap5", RENDER, FLAGS, wrap, 0) \
    X(WRAP6, "Wrap6", RENDER, FLAGS, wrap, 0) \
    X(WRAP7, "Wrap7", RENDER, FLAGS, wrap, 0) \
    X(CLIPPING, "Clipping", RENDER, BOOL, NONE, 0) \
    X(LIGHTING, "Lighting", RENDER, BOOL, NONE, 0) \
    X(AMBIENT, "Ambient", RENDER, COLOR, NONE, 0) \
    X(FOGVERTEXMODE, "FogVertexMode", RENDER, ENUM, fog, 0) \
    X(COLORVERTEX, "ColorVertex", RENDER, BOOL, NONE, 0) \
    X(LOCALVIEWER, "LocalViewer", RENDER, BOOL, NONE, 0) \
    X(NORMALIZENORMALS, "NormalizeNormals", RENDER, BOOL, NONE, 0) \
    X(DIFFUSEMATERIALSOURCE, "DiffuseMaterialSource", RENDER, ENUM, mcs, 0) \
    X(SPECULARMATERIALSOURCE, "SpecularMaterialSource", RENDER, ENUM, mcs, 0) \
    X(AMBIENTMATERIALSOURCE, "AmbientMaterialSource", RENDER, ENUM, mcs, 0) \
    X(EMISSIVEMATERIALSOURCE, "EmissiveMaterialSource", RENDER, ENUM, mcs, 0) \
    X(VERTEXBLEND, "VertexBlend", RENDER, ENUM, vbf, 0) \
    X(CLIPPLANEENABLE, "ClipPlaneEnable", RENDER, FLAGS, clipplane, 0) \
    X(POINTSIZE, "PointSize", RENDER, FLOAT, NONE, 0) \
    X(POINTSIZE_MIN, "PointSize_Min", RENDER, FLOAT, NONE, 0) \
    X(POINTSPRITEENABLE, "PointSpriteEnable", RENDER, BOOL, NONE, 0) \
    X(POINTSCALEENABLE, "PointScaleEnable", RENDER, BOOL, NONE, 0) \
    X(POINTSCALE_A, "PointScale_A", RENDER, FLOAT, NONE, 0) \
    X(POINTSCALE_B, "PointScale_B", RENDER, FLOAT, NONE, 0) \
    X(POINTSCALE_C, "PointScale_C", RENDER, FLOAT, NONE, 0) \
    X(MULTISAMPLEANTIALIAS, "MultiSampleAntiAlias", RENDER, BOOL, NONE, 0) \
    X(MULTISAMPLEMASK, "MultiSampleMask", RENDER, INT, NONE, 0) \
    X(PATCHEDGESTYLE, "PatchEdgeStyle", RENDER, ENUM, patchedge, 0) \
    X(DEBUGMONITORTOKEN, "DebugMonitorToken", RENDER, ENUM, dmt, 0) \
    X(POINTSIZE_MAX, "PointSize_Max", RENDER, FLOAT, NONE, 0) \
    X(INDEXEDVERTEXBLENDENABLE, "IndexedVertexBlendEnable", RENDER, BOOL, NONE, 0) \
    X(COLORWRITEENABLE, "ColorWriteEnable", RENDER, FLAGS, colorwrite, 0) \
    X(TWEENFACTOR, "TweenFactor", RENDER, FLOAT, NONE, 0) \
    X(BLENDOP, "BlendOp", RENDER, ENUM, blendop, 0) \
    X(POSITIONDEGREE, "PositionDegree", RENDER, ENUM, degree, 0) \
    X(NORMALDEGREE, "NormalDegree", RENDER, ENUM, degree, 0) \
    X(SCISSORTESTENABLE, "ScissorTestEnable", RENDER, BOOL, NONE, 0) \
    X(SLOPESCALEDEPTHBIAS, "SlopeScaleDepthBias", RENDER, FLOAT, NONE, 0) \
    X(ANTIALIASEDLINEENABLE, "AntiAliasedLineEnable", RENDER, BOOL, NONE, 0) \
    X(MINTESSELLATIONLEVEL, "MinTessellationLevel", RENDER, FLOAT, NONE, 0) \
    X(MAXTESSELLATIONLEVEL, "MaxTessellationLevel", RENDER, FLOAT, NONE, 0) \
    X(ADAPTIVETESS_X, "AdaptiveTess_X", RENDER, FLOAT, NONE, 0) \
    X(ADAPTIVETESS_Y, "AdaptiveTess_Y", RENDER, FLOAT, NONE, 0) \
    X(ADAPTIVETESS_Z, "AdaptiveTess_Z", RENDER, FLOAT, NONE, 0) \
    X(ADAPTIVETESS_W, "AdaptiveTess_W", RENDER, FLOAT, NONE, 0) \
    X(ENABLEADAPTIVETESSELLATION, "EnableAdaptiveTessellation", RENDER, BOOL, NONE, 0) \
    X(TWOSIDEDSTENCILMODE, "TwoSidedStencilMode", RENDER, BOOL, NONE, 0) \
    X(CCW_STENCILFAIL, "CCW_StencilFail", RENDER, ENUM, stencilop, 0) \
    X(CCW_STENCILZFAIL, "CCW_StencilZFail", RENDER, ENUM, stencilop, 0) \
    X(CCW_STENCILPASS, "CCW_StencilPass", RENDER, ENUM, stencilop, 0) \
    X(CCW_STENCILFUNC, "CCW_StencilFunc", RENDER, ENUM, cmp, 0) \
    X(COLORWRITEENABLE1, "ColorWriteEnable1", RENDER, FLAGS, colorwrite, 0) \
    X(COLORWRITEENABLE2, "ColorWriteEnable2", RENDER, FLAGS, colorwrite, 0) \
    X(COLORWRITEENABLE3, "ColorWriteEnable3", RENDER, FLAGS, colorwrite, 0) \
    X(BLENDFACTOR, "BlendFactor", RENDER, COLOR, NONE, 0) \
    X(SRGBWRITEENABLE, "SRGBWriteEnable", RENDER, BOOL, NONE, 0) \
    X(DEPTHBIAS, "DepthBias", RENDER, FLOAT, NONE, 0) \
    X(WRAP8, "Wrap8", RENDER, FLAGS, wrap, 0) \
    X(WRAP9, "Wrap9", RENDER, FLAGS, wrap, 0) \
    X(WRAP10, "Wrap10", RENDER, FLAGS, wrap, 0) \
    X(WRAP11, "Wrap11", RENDER, FLAGS, wrap, 0) \
    X(WRAP12, "Wrap12", RENDER, FLAGS, wrap, 0) \
    X(WRAP13, "Wrap13", RENDER, FLAGS, wrap, 0) \
    X(WRAP14, "Wrap14", RENDER, FLAGS, wrap, 0) \
    X(WRAP15, "Wrap15", RENDER, FLAGS, wrap, 0) \
    X(SEPARATEALPHABLENDENABLE, "SeparateAlphaBlendEnable", RENDER, BOOL, NONE, 0) \
    X(SRCBLENDALPHA, "SrcBlendAlpha", RENDER, ENUM, blend, 0) \
    X(DESTBLENDALPHA, "DestBlendAlpha", RENDER, ENUM, blend, 0) \
    X(BLENDOPALPHA, "BlendOpAlpha", RENDER, ENUM, blendop, 0) \
    /* texture stage states (D3DTSS_*), [n] = stage */ \
    X(COLOROP, "ColorOp", STAGE, ENUM, top, 7) \
    X(COLORARG0, "ColorArg0", STAGE, FLAGS, ta, 7) \
    X(COLORARG1, "ColorArg1", STAGE, FLAGS, ta, 7) \
    X(COLORARG2, "ColorArg2", STAGE, FLAGS, ta, 7) \
    X(ALPHAOP, "AlphaOp", STAGE, ENUM, top, 7) \
    X(ALPHAARG0, "AlphaArg0", STAGE, FLAGS, ta, 7) \
    X(ALPHAARG1, "AlphaArg1", STAGE, FLAGS, ta, 7) \
    X(ALPHAARG2, "AlphaArg2", STAGE, FLAGS, ta, 7) \
    X(RESULTARG, "ResultArg", STAGE, FLAGS, ta, 7) \
    X(BUMPENVMAT00, "BumpEnvMat00", STAGE, FLOAT, NONE, 7) \
    X(BUMPENVMAT01, "BumpEnvMat01", STAGE, FLOAT, NONE, 7) \
    X(BUMPENVMAT10, "BumpEnvMat10", STAGE, FLOAT, NONE, 7) \
    X(BUMPENVMAT11, "BumpEnvMat11", STAGE, FLOAT, NONE, 7) \
    X(TEXCOORDINDEX, "TexCoordIndex", STAGE, FLAGS, tci, 7) \
    X(BUMPENVLSCALE, "BumpEnvLScale", STAGE, FLOAT, NONE, 7) \
    X(BUMPENVLOFFSET, "BumpEnvLOffset", STAGE, FLOAT, NONE, 7) \
    X(TEXTURETRANSFORMFLAGS, "TextureTransformFlags", STAGE, FLAGS, ttff, 7) \
    X(CONSTANT, "Constant", STAGE, COLOR, NONE, 7) \
    /* fixed function */ \
    X(NPATCHMODE, "NPatchMode", FIXED, FLOAT, NONE, 0) \
    X(FVF, "FVF", FIXED, INT, NONE, 0) \
    X(PROJECTIONTRANSFORM, "ProjectionTransform", FIXED, MATRIX, NONE, 0) \
    X(VIEWTRANSFORM, "ViewTransform", FIXED, MATRIX, NONE, 0) \
    X(WORLDTRANSFORM, "WorldTransform", FIXED, MATRIX, NONE, 255) \
    X(TEXTURETRANSFORM, "TextureTransform", FIXED, MATRIX, NONE, 7) \
    X(MATERIALDIFFUSE, "MaterialDiffuse", FIXED, COLOR, NONE, 0) \
    X(MATERIALAMBIENT, "MaterialAmbient", FIXED, COLOR, NONE, 0) \
    X(MATERIALSPECULAR, "MaterialSpecular", FIXED, COLOR, NONE, 0) \
    X(MATERIALEMISSIVE, "MaterialEmissive", FIXED, COLOR, NONE, 0) \
    X(MATERIALPOWER, "MaterialPower", FIXED, FLOAT, NONE, 0) \
    X(LIGHTTYPE, "LightType", FIXED, ENUM, light, 255) \
    X(LIGHTDIFFUSE, "LightDiffuse", FIXED, COLOR, NONE, 255) \
    X(LIGHTSPECULAR, "LightSpecular", FIXED, COLOR, NONE, 255) \
    X(LIGHTAMBIENT, "LightAmbient", FIXED, COLOR, NONE, 255) \
    X(LIGHTPOSITION, "LightPosition", FIXED, VECTOR, NONE, 255) \
    X(LIGHTDIRECTION, "LightDirection", FIXED, VECTOR, NONE, 255) \
    X(LIGHTRANGE, "LightRange", FIXED, FLOAT, NONE, 255) \
    X(LIGHTFALLOFF, "LightFalloff", FIXED, FLOAT, NONE, 255) \
    X(LIGHTATTENUATION0, "LightAttenuation0", FIXED, FLOAT, NONE, 255) \
    X(LIGHTATTENUATION1, "LightAttenuation1", FIXED, FLOAT, NONE, 255) \
    X(LIGHTATTENUATION2, "LightAttenuation2", FIXED, FLOAT, NONE, 255) \
    X(LIGHTTHETA, "LightTheta", FIXED, FLOAT, NONE, 255) \
    X(LIGHTPHI, "LightPhi", FIXED, FLOAT, NONE, 255) \
    X(LIGHTENABLE, "LightEnable", FIXED, BOOL, NONE, 255) \
    /* shaders */ \
    X(VERTEXSHADER, "VertexShader", SHADER, SHADER, NONE, 0) \
    X(PIXELSHADER, "PixelShader", SHADER, SHADER, NONE, 0) \
    /* shader constants (asm-era effects), [n] = register */ \
    X(VERTEXSHADERCONSTANTF, "VertexShaderConstantF", FIXED, VECTOR, NONE, 255) \
    X(VERTEXSHADERCONSTANTB, "VertexShaderConstantB", FIXED, VECTOR, NONE, 15) \
    X(VERTEXSHADERCONSTANTI, "VertexShaderConstantI", FIXED, VECTOR, NONE, 15) \
    X(VERTEXSHADERCONSTANT, "VertexShaderConstant", FIXED, VECTOR, NONE, 255) \
    X(VERTEXSHADERCONSTANT1, "VertexShaderConstant1", FIXED, VECTOR, NONE, 255) \
    X(VERTEXSHADERCONSTANT2, "VertexShaderConstant2", FIXED, VECTOR, NONE, 255) \
    X(VERTEXSHADERCONSTANT3, "VertexShaderConstant3", FIXED, VECTOR, NONE, 255) \
    X(VERTEXSHADERCONSTANT4, "VertexShaderConstant4", FIXED, VECTOR, NONE, 255) \
    X(PIXELSHADERCONSTANTF, "PixelShaderConstantF", FIXED, VECTOR, NONE, 223) \
    X(PIXELSHADERCONSTANTB, "PixelShaderConstantB", FIXED, VECTOR, NONE, 15) \
    X(PIXELSHADERCONSTANTI, "PixelShaderConstantI", FIXED, VECTOR, NONE, 15) \
    X(PIXELSHADERCONSTANT, "PixelShaderConstant", FIXED, VECTOR, NONE, 223) \
    X(PIXELSHADERCONSTANT1, "PixelShaderConstant1", FIXED, VECTOR, NONE, 223) \
    X(PIXELSHADERCONSTANT2, "PixelShaderConstant2", FIXED, VECTOR, NONE, 223) \
    X(PIXELSHADERCONSTANT3, "PixelShaderConstant3", FIXED, VECTOR, NONE, 223) \
    X(PIXELSHADERCONSTANT4, "PixelShaderConstant4", FIXED, VECTOR, NONE, 223) \
    /* textures: Texture[n] in a pass, Texture in a sampler_state */ \
    X(TEXTURE, "Texture", TEXTURE, TEXTURE, NONE, 15) \
    /* sampler states (D3DSAMP_*): in sampler_state, or in a pass with [n] = sampler */ \
    X(ADDRESSU, "AddressU", SAMPLER, ENUM, taddress, 15) \
    X(ADDRESSV, "AddressV", SAMPLER, ENUM, taddress, 15) \
    X(ADDRESSW, "AddressW", SAMPLER, ENUM, taddress, 15) \
    X(BORDERCOLOR, "BorderColor", SAMPLER, COLOR, NONE, 15) \
    X(MAGFILTER, "MagFilter", SAMPLER, ENUM, texf, 15) \
    X(MINFILTER, "MinFilter", SAMPLER, ENUM, texf, 15) \
    X(MIPFILTER, "MipFilter", SAMPLER, ENUM, texf, 15) \
    X(MIPMAPLODBIAS, "MipMapLodBias", SAMPLER, FLOAT, NONE, 15) \
    X(MAXMIPLEVEL, "MaxMipLevel", SAMPLER, INT, NONE, 15) \
    X(MAXANISOTROPY, "MaxAnisotropy", SAMPLER, INT, NONE, 15) \
    X(SRGBTEXTURE, "SRGBTexture", SAMPLER, BOOL, NONE, 15) \
    X(ELEMENTINDEX, "ElementIndex", SAMPLER, INT, NONE, 15) \
    X(DMAPOFFSET, "DMapOffset", SAMPLER, INT, NONE, 15) \
    /* Sampler[n] = <s>: a whole sampler_state bound to stage n from a pass */ \
    X(SAMPLER, "Sampler", SAMPLER, SAMPLER, NONE, 15) \
    X(CLIPPLANE, "ClipPlane", FIXED, VECTOR, NONE, 5)

#endif
