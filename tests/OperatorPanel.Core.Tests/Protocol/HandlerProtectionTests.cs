using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Core.Tests.Protocol;

/// <summary>The V bytes a protocol 3 handler with the default settings refuses although the CPU would write them (docs/protocol.md, 83).</summary>
public sealed class HandlerProtectionTests
{
    [Theory]
    [InlineData(CpuModel.Cpu221, "VB1442", "VB1442-VB2047", "VB1870-VB2047")] // 2048 V bytes: full 606 from 1442, compact 178 from 1870
    [InlineData(CpuModel.Cpu224, "VD8188", "VB7586-VB8191", "VB8014-VB8191")]
    [InlineData(CpuModel.Cpu226, "VW9633", "VB9634-VB10239", "VB10062-VB10239")] // touches the first byte only
    public void Refusal_HandlersOwnVBytesAtTheTopOfV_NamesTheFullAndTheCompactRange(CpuModel model, string address, string full, string compact)
    {
        HandlerProtection.Refusal(PlcAddress.Parse(address), CpuProfiles.For(model)).Should().Be(
            $"{address} is in the handler's own V bytes {full} (where generate puts the full handler's buffer, work bytes and list by default; "
            + $"the compact handler's are {compact}; IDENTIFY says where a station's are)");
    }

    [Theory]
    [InlineData("VB100")]
    [InlineData("VB9633")]
    [InlineData("SMB30")] // SM is refused by the link's rule (LinkAreas), not here
    [InlineData("QB0")]
    public void Refusal_BytesTheHandlerLeavesAlone_IsNull(string address)
    {
        HandlerProtection.Refusal(PlcAddress.Parse(address), CpuProfiles.For(CpuModel.Cpu226)).Should().BeNull();
    }

    [Theory]
    [InlineData(CpuModel.Cpu226, false, "VB9634", "VB9634-VB10239", "the full handler's buffer, work bytes and list")]
    [InlineData(CpuModel.Cpu226, true, "VD10236", "VB10062-VB10239", "the compact handler's buffer and work bytes")] // 178 bytes
    [InlineData(CpuModel.Cpu221, true, "V1870.0", "VB1870-VB2047", "the compact handler's buffer and work bytes")]
    public void Refusal_StationsHandler_NamesThatHandlersRangeOnly(CpuModel model, bool compact, string address, string range, string what)
    {
        HandlerProtection.Refusal(PlcAddress.Parse(address), CpuProfiles.For(model), compact).Should().Be(
            $"{address} is in the handler's own V bytes {range} (where generate puts {what} by default; IDENTIFY says where a station's are)");
    }

    [Fact]
    public void Refusal_CompactStation_LeavesTheFullHandlersBytesBelowItsOwnWritable()
    {
        // VB9634-VB10061 belong to the full handler only: a compact station keeps the program's bytes there.
        HandlerProtection.Refusal(PlcAddress.Parse("VW10060"), CpuProfiles.For(CpuModel.Cpu226), compact: true).Should().BeNull();
        HandlerProtection.Refusal(PlcAddress.Parse("VW10060"), CpuProfiles.For(CpuModel.Cpu226), compact: false)
            .Should().StartWith("VW10060 is in the handler's own V bytes VB9634-VB10239 ");
    }

    [Fact]
    public void OwnVBytes_FullAndCompact_AreTheTopOfVOnAnEvenByte()
    {
        HandlerProtection.OwnVBytes(CpuProfiles.For(CpuModel.Cpu224), compact: false).Should().Be((7586, 8191));
        HandlerProtection.OwnVBytes(CpuProfiles.For(CpuModel.Cpu224), compact: true).Should().Be((8014, 8191));
    }

    [Theory]
    [InlineData(false, "VB1000", "VB1000-VB1605", "the full handler's buffer, work bytes and list")]
    [InlineData(false, "VW1604", "VB1000-VB1605", "the full handler's buffer, work bytes and list")]
    [InlineData(true, "VD1176", "VB1000-VB1177", "the compact handler's buffer and work bytes")] // touches the last byte only
    public void Refusal_HandlerTheProjectMoved_NamesItsRangeAndThatTheProjectSaysSo(bool compact, string address, string range, string what)
    {
        HandlerProtection.Refusal(PlcAddress.Parse(address), CpuProfiles.For(CpuModel.Cpu224), compact, vFirst: 1000).Should().Be(
            $"{address} is in the handler's own V bytes {range} (where the project's \"handlerVFirst\" puts {what}; IDENTIFY says where a station's are)");
    }

    [Theory]
    [InlineData("VB999")]
    [InlineData("VB1606")]
    [InlineData("VB8000")] // the default place's bytes are the program's when the handler is elsewhere
    public void Refusal_HandlerTheProjectMoved_LeavesEveryOtherVByteWritable(string address)
    {
        HandlerProtection.Refusal(PlcAddress.Parse(address), CpuProfiles.For(CpuModel.Cpu224), compact: false, vFirst: 1000).Should().BeNull();
    }

    [Fact]
    public void OwnVBytes_HandlerTheProjectMoved_StartsThereForItsShapesBytes()
    {
        HandlerProtection.OwnVBytes(CpuProfiles.For(CpuModel.Cpu224), compact: false, vFirst: 1000).Should().Be((1000, 1605));
        HandlerProtection.OwnVBytes(CpuProfiles.For(CpuModel.Cpu224), compact: true, vFirst: 1000).Should().Be((1000, 1177));
    }
}
