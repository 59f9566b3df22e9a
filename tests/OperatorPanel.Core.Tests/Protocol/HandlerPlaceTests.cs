using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Protocol.V3;

namespace OperatorPanel.Core.Tests.Protocol;

/// <summary>Where a protocol 3 handler's V bytes may lie: from VB3 on, the whole handler inside the CPU's V (STL005's rule).</summary>
public sealed class HandlerPlaceTests
{
    [Theory]
    [InlineData(3, false)]
    [InlineData(7586, false)] // 8192 - 606
    [InlineData(8014, true)] //  8192 - 178
    public void Problem_FirstAndLastPlaceThatFits_IsNull(int vFirst, bool compact)
    {
        HandlerPlace.Problem(vFirst, HandlerShape.Of(compact), CpuProfiles.For(CpuModel.Cpu224)).Should().BeNull();
    }

    [Fact]
    public void Problem_BelowVB3_SaysWhyTheFrameCheckNeedsThreeBytesBefore()
    {
        HandlerPlace.Problem(2, HandlerShape.Full, CpuProfiles.For(CpuModel.Cpu224)).Should().Be(
            "the handler needs VB2-VB607 (606 bytes) but the CPU 224 has VB0-VB8191 and a protocol 3 handler starts at VB3 or later "
            + "(its frame check points 3 bytes before its V bytes)");
    }

    [Fact]
    public void Problem_PastTheEndOfV_NamesTheBytesNeededAndTheCpusV()
    {
        HandlerPlace.Problem(1443, HandlerShape.Full, CpuProfiles.For(CpuModel.Cpu221)).Should().Be(
            "the handler needs VB1443-VB2048 (606 bytes) but the CPU 221 has VB0-VB2047");
    }

    [Fact]
    public void HighestVFirst_FullAndCompact_EndOnTheLastVByte()
    {
        HandlerPlace.HighestVFirst(HandlerShape.Full, 8192).Should().Be(7586);
        HandlerPlace.HighestVFirst(HandlerShape.Compact, 8192).Should().Be(8014);
        HandlerPlace.Range(1000, HandlerShape.Full).Should().Be((1000, 1605));
    }
}
