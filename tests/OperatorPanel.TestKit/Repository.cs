namespace OperatorPanel.TestKit;

/// <summary>The checkout the tests run from: the folder holding OperatorPanel.sln, above the test's binaries.</summary>
public static class Repository
{
    public static string Root()
    {
        var dir = new DirectoryInfo(AppContext.BaseDirectory);
        while (dir is not null && !File.Exists(Path.Combine(dir.FullName, "OperatorPanel.sln")))
        {
            dir = dir.Parent;
        }

        return dir?.FullName ?? throw new InvalidOperationException("OperatorPanel.sln not found above " + AppContext.BaseDirectory);
    }
}
