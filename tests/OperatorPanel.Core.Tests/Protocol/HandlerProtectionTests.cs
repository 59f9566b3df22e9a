using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Core.Tests.Protocol;

/// <summary>The bytes a handler refuses although the CPU would write them (docs/protocol-v2.md, error 03).</summary>
public sealed class HandlerProtectionTests
{
    [Theory]
    [InlineData("SMB30", 0, "SMB30 is port 0's Freeport control byte, which the handler sets")]
    [InlineData("SMW29", 0, "SMW29 touches SMB30, which is port 0's Freeport control byte, which the handler sets")]
    [InlineData("SMB130", 1, "SMB130 is port 1's Freeport control byte, which the handler sets")]
    [InlineData("SMB90", 0, "SMB90 is in port 0's receive message control SMB86-SMB94, which the handler's RCV uses")]
    [InlineData("SMB34", 0, "SMB34 is the timed interrupt 0 interval, the handler's reply delay")]
    public void Refusal_HandlersOwnSmBytes_SaysWhose(string address, int port, string message)
    {
        HandlerProtection.Refusal(PlcAddress.Parse(address), CpuProfiles.For(CpuModel.Cpu226), port).Should().Be(message);
    }

    [Fact]
    public void Refusal_HandlersOwnVBytesAtTheEndOfV_NamesTheRange()
    {
        // CPU 226: 10240 V bytes; the default handler keeps the last 256 + 52 + 120 = 428.
        HandlerProtection.Refusal(PlcAddress.Parse("VB9900"), CpuProfiles.For(CpuModel.Cpu226)).Should()
            .Be("VB9900 is in the handler's own V bytes VB9812-VB10239 (frame buffer, work bytes, READ CHANGES copies; where generate puts them by default)");
    }

    [Theory]
    [InlineData("VB100")]
    [InlineData("VB9811")]
    [InlineData("SMB130")] // port 1's byte, with the handler on port 0
    [InlineData("QB0")]
    public void Refusal_BytesTheHandlerLeavesAlone_IsNull(string address)
    {
        HandlerProtection.Refusal(PlcAddress.Parse(address), CpuProfiles.For(CpuModel.Cpu226)).Should().BeNull();
    }
}
