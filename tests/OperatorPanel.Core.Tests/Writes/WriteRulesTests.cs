using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Projects;
using OperatorPanel.Core.Transport;
using OperatorPanel.Core.Writes;
using OperatorPanel.TestKit;

namespace OperatorPanel.Core.Tests.Writes;

/// <summary>
/// The project's write rules, the same for <c>opanel write</c> and the Memory window: a read-only tag binds every byte it
/// has, however a write names it, and the station's handler keeps its own V bytes.
/// </summary>
public sealed class WriteRulesTests
{
    private static readonly ProjectStation Filler = Station(
        [Tag("TankLevel", "VW150", writable: false), Tag("Running", "V160.2", writable: false), Tag("Outputs", "QB0", writable: false), Tag("Recipe", "VB110", writable: true)],
        outputs: [new IoSymbol("Pump", PlcAddress.Parse("Q0.1"), string.Empty)]);

    [Theory]
    [InlineData("VW150", "VW150 is part of tag TankLevel, which the project marks read-only")]
    [InlineData("VB151", "VB151 is part of tag TankLevel (VW150), which the project marks read-only")]
    [InlineData("V150.3", "V150.3 is part of tag TankLevel (VW150), which the project marks read-only")]
    [InlineData("VD148", "VD148 overlaps tag TankLevel (VW150), which the project marks read-only")]
    [InlineData("VW151", "VW151 overlaps tag TankLevel (VW150), which the project marks read-only")]
    [InlineData("VB160", "VB160 overlaps tag Running (V160.2), which the project marks read-only")]
    [InlineData("V160.2", "V160.2 is part of tag Running, which the project marks read-only")]
    [InlineData("QB0", "QB0 is part of tag Outputs, which the project marks read-only")]
    public void Refusal_AnyByteOfAReadOnlyTag_IsRefusedNamingTheTag(string address, string message)
    {
        WriteRules.Refusal(PlcAddress.Parse(address), Filler).Should().Be(message);
    }

    [Theory]
    [InlineData("VB149")] //   just below TankLevel
    [InlineData("VW152")] //   just above it
    [InlineData("V160.3")] //  WRITE BITS changes its own bit: Running's bit stays
    [InlineData("VB110")] //   a writable tag
    [InlineData("Q0.1")] //    an output the project lists: the Output window switches it, whatever tag shows QB0
    [InlineData("MW150")] //   another area
    public void Refusal_BytesNoReadOnlyTagHas_IsNull(string address)
    {
        WriteRules.Refusal(PlcAddress.Parse(address), Filler).Should().BeNull();
    }

    [Theory]
    [InlineData(false, "VB7586", "VB7586 is in the handler's own V bytes VB7586-VB8191 (where generate puts the full handler's buffer, work bytes and list by default")]
    [InlineData(true, "VB8014", "VB8014 is in the handler's own V bytes VB8014-VB8191 (where generate puts the compact handler's buffer and work bytes by default")]
    public void Refusal_FreeportStation_RefusesItsHandlersOwnVBytes(bool compact, string address, string message)
    {
        WriteRules.Refusal(PlcAddress.Parse(address), Filler with { Compact = compact }).Should().StartWith(message);
    }

    [Fact]
    public void Refusal_CompactStation_WritesTheBytesOnlyTheFullHandlerWouldKeep()
    {
        WriteRules.Refusal(PlcAddress.Parse("VB8000"), Filler with { Compact = true }).Should().BeNull();
    }

    [Fact]
    public void Refusal_PpiStation_HasNoHandlerBytes()
    {
        var ppi = Filler with { Link = Filler.Link with { Protocol = LinkProtocol.Ppi } };

        WriteRules.Refusal(PlcAddress.Parse("VB8000"), ppi).Should().BeNull();
        WriteRules.Refusal(PlcAddress.Parse("VB151"), ppi).Should().Contain("tag TankLevel", "the project's read-only tags hold on every link");
    }

    [Fact]
    public void Refusal_WithoutProject_KnowsNoTagsAndTakesTheFullHandler()
    {
        var cpu = Some.Cpu(CpuModel.Cpu224);

        WriteRules.Refusal(PlcAddress.Parse("VW150"), LinkProtocol.Freeport, cpu, station: null).Should().BeNull();
        WriteRules.Refusal(PlcAddress.Parse("VB8000"), LinkProtocol.Freeport, cpu, station: null).Should().StartWith("VB8000 is in the handler's own V bytes VB7586-VB8191");
        WriteRules.Refusal(PlcAddress.Parse("VB8000"), LinkProtocol.Freeport, cpu: null, station: null).Should().BeNull("without a CPU the size of V is unknown");
    }

    private static ProjectStation Station(ImmutableArray<ProjectTag> tags, ImmutableArray<IoSymbol> outputs) =>
        new("Filler", new Station(2), Some.Cpu(CpuModel.Cpu224), Some.SerialSettings(), [], outputs, tags, []);

    private static ProjectTag Tag(string symbol, string address, bool writable)
    {
        var at = PlcAddress.Parse(address);
        return new ProjectTag(symbol, at, DisplayFormats.DefaultFor(at), writable, string.Empty);
    }
}
