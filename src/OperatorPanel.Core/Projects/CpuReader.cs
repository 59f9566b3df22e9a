using OperatorPanel.Core.Cpu;

namespace OperatorPanel.Core.Projects;

/// <summary>Reads a station's <c>cpu</c> object: <c>{ "model": "224", "revision": "current" }</c>.</summary>
internal static class CpuReader
{
    public static CpuProfile? Read(JsonFields? fields)
    {
        if (fields is null)
        {
            return null;
        }

        fields.ReportUnknown("model", "revision");
        var modelText = fields.String("model");
        var revisionText = fields.String("revision", JsonWords.Of(CpuRevision.Current));
        CpuModel? model = null;
        if (modelText is not null && CpuModelNames.TryParse(modelText, out var parsedModel, out _))
        {
            model = parsedModel;
        }
        else if (modelText is not null)
        {
            var supported = string.Join(", ", Enum.GetValues<CpuModel>().Select(CpuModelNames.ShortName));
            fields.Problem("model", $"unknown CPU model '{JsonPath.Shorten(modelText)}'; supported: {supported}");
        }

        CpuRevision? revision = null;
        if (revisionText is not null && JsonWords.TryParse<CpuRevision>(revisionText, out var parsedRevision))
        {
            revision = parsedRevision;
        }
        else if (revisionText is not null)
        {
            fields.Problem("revision", $"unknown CPU revision '{JsonPath.Shorten(revisionText)}'; use {JsonWords.List<CpuRevision>()}");
        }

        if (model is not { } m || revision is not { } r)
        {
            return null;
        }

        if (!CpuProfiles.TryFor(m, r, out var profile))
        {
            var exists = string.Join(", ", CpuProfiles.RevisionsOf(m).Select(JsonWords.Of));
            fields.Problem("revision", $"{CpuModelNames.Format(m)} has no {JsonWords.Of(r)} revision; it exists as: {exists}");
            return null;
        }

        return profile;
    }
}
