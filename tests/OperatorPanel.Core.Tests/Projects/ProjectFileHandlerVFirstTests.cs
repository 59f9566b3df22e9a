using OperatorPanel.Core.Projects;

namespace OperatorPanel.Core.Tests.Projects;

/// <summary>
/// A station's "handlerVFirst" (where its handler was generated, <c>generate --buffer</c>): absent is the top of V and
/// leaves the file as it was; written only when set and kept through save and load; checked with the generator's own
/// rule (STL005: VB3 or later, the whole handler inside the CPU's V), a wrong value named at its place.
/// </summary>
public sealed class ProjectFileHandlerVFirstTests
{
    private const string Allowed = "(leave it out for the top of V, where generate puts it by default)";

    [Fact]
    public void Parse_FileWithoutTheField_DefaultPlaceAndSavedWithoutIt()
    {
        var project = ProjectFile.Parse(SampleProject.Text).Project!;

        project.Stations[0].HandlerVFirst.Should().BeNull();
        ProjectFile.Format(project).Should().NotContain("handlerVFirst", "a project whose handler is at the top of V keeps the file it always had");
    }

    [Fact]
    public void Format_HandlerVFirst_WrittenAndRoundTrips()
    {
        var project = ProjectFile.Parse(SampleProject.Text).Project!;
        var edited = project with { Stations = [project.Stations[0] with { HandlerVFirst = 1000 }] };

        var text = ProjectFile.Format(edited);
        var reloaded = ProjectFile.Parse(text).Project!;

        text.Should().Contain("\"handlerVFirst\": 1000");
        reloaded.Stations[0].HandlerVFirst.Should().Be(1000);
        reloaded.Should().BeEquivalentTo(edited, o => o.ComparingRecordsByMembers());
    }

    [Theory]
    [InlineData(3)] //    the lowest: the frame check points 3 bytes before it
    [InlineData(7586)] // the highest for the full handler's 606 bytes on a CPU 224 (8192 V bytes)
    public void Parse_EndsOfTheAllowedRange_Load(int vFirst)
    {
        var tree = SampleProject.Tree();
        tree.Station()["handlerVFirst"] = vFirst;

        ProjectFile.Parse(tree.ToJsonString()).Project!.Stations[0].HandlerVFirst.Should().Be(vFirst);
    }

    [Fact]
    public void Parse_CompactStation_MayStartHigherThanTheFullHandler()
    {
        // 178 V bytes: the compact handler fits from VB8014 on a CPU 224; the full one would end past VB8191.
        var tree = SampleProject.Tree();
        tree.Station()["compact"] = true;
        tree.Station()["allowStop"] = false;
        tree.Station()["handlerVFirst"] = 8014;

        ProjectFile.Parse(tree.ToJsonString()).Project!.Stations[0].HandlerVFirst.Should().Be(8014);
    }

    [Theory]
    [InlineData(2, "the handler needs VB2-VB607 (606 bytes) but the CPU 224 has VB0-VB8191 and a protocol 3 handler starts at VB3 or later "
        + "(its frame check points 3 bytes before its V bytes); \"handlerVFirst\" may be 3-7586 for the full handler " + Allowed)]
    [InlineData(7587, "the handler needs VB7587-VB8192 (606 bytes) but the CPU 224 has VB0-VB8191; \"handlerVFirst\" may be 3-7586 for the full handler " + Allowed)]
    [InlineData(-4, "-4 is not a V byte; \"handlerVFirst\" may be 3-7586 for the full handler " + Allowed)]
    public void Parse_PlaceTheGeneratorRefuses_NamesTheRangeAndWhatIsAllowed(int vFirst, string message)
    {
        BadFile.Expect(t => t.Station()["handlerVFirst"] = vFirst, "$.stations[0].handlerVFirst", message);
    }

    [Fact]
    public void Parse_CompactHandlerPastTheEndOfV_NamesTheCompactRange()
    {
        BadFile.Expect(
            t =>
            {
                t.Station()["compact"] = true;
                t.Station()["allowStop"] = false;
                t.Station()["handlerVFirst"] = 8015;
            },
            "$.stations[0].handlerVFirst",
            "the handler needs VB8015-VB8192 (178 bytes) but the CPU 224 has VB0-VB8191; \"handlerVFirst\" may be 3-8014 for the compact handler " + Allowed);
    }

    [Fact]
    public void Parse_AddressTextInsteadOfANumber_NamesTheField()
    {
        BadFile.Expect(t => t.Station()["handlerVFirst"] = "VB1000", "$.stations[0].handlerVFirst", "expected a whole number, found the string \"VB1000\"");
    }

    [Fact]
    public void Parse_FractionalNumber_NamesTheField()
    {
        BadFile.Expect(t => t.Station()["handlerVFirst"] = 1000.5, "$.stations[0].handlerVFirst", "expected a whole number, found 1000.5");
    }
}
