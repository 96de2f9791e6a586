#include "GlslLexer.h"

#include <QColor>
#include <QFont>

namespace sdfwb::widgets {

GlslLexer::GlslLexer(QObject* parent) : QsciLexerCPP(parent) {
    QFont font("Monospace", 10);
    font.setStyleHint(QFont::TypeWriter);
    setDefaultFont(font);
    for (int style = 0; style < 128; ++style) setFont(font, style);
    setColor(QColor(0x1a, 0x5f, 0xb4), Keyword);
    setColor(QColor(0x8a, 0x3f, 0xa0), KeywordSet2);
    setColor(QColor(0x5e, 0x7d, 0x3a), Comment);
    setColor(QColor(0x5e, 0x7d, 0x3a), CommentLine);
    setColor(QColor(0x5e, 0x7d, 0x3a), CommentDoc);
    setColor(QColor(0xb0, 0x5a, 0x00), Number);
    setColor(QColor(0x80, 0x80, 0x80), PreProcessor);
}

const char* GlslLexer::keywords(int set) const {
    switch (set) {
    case 1:
        return "attribute break buffer case centroid coherent const continue default discard do else false flat for "
               "highp if in inout invariant layout lowp mediump noperspective out patch precise precision readonly "
               "restrict return sample shared smooth struct subroutine switch true uniform varying volatile while "
               "writeonly";
    case 2:
        return "void bool int uint float double vec2 vec3 vec4 dvec2 dvec3 dvec4 bvec2 bvec3 bvec4 ivec2 ivec3 ivec4 "
               "uvec2 uvec3 uvec4 mat2 mat3 mat4 mat2x2 mat2x3 mat2x4 mat3x2 mat3x3 mat3x4 mat4x2 mat4x3 mat4x4 "
               "sampler1D sampler2D sampler3D samplerCube image2D "
               "abs acos acosh all any asin asinh atan atanh ceil clamp cos cosh cross degrees determinant distance "
               "dot equal exp exp2 faceforward floatBitsToInt floatBitsToUint floor fma fract inverse inversesqrt "
               "intBitsToFloat isinf isnan length log log2 matrixCompMult max min mix mod modf normalize not notEqual "
               "outerProduct pow radians reflect refract round roundEven sign sin sinh smoothstep sqrt step tan tanh "
               "texelFetch texture textureLod transpose trunc uintBitsToFloat dFdx dFdy fwidth "
               "sdf Point3 Vector3 Color3 Radiance3 float2 float3 float4 pi saturate lerp square frac lengthSquared";
    default:
        return nullptr;
    }
}

} // namespace sdfwb::widgets
